// r3: store at a periodic shifted index o[i == 0 ? n - 1 : i - 1] (a bijection)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_store_periodic(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i == 0 ? n - 1 : i - 1] = a[i] * a[i] + a[n - 1 - i];
}
