// adversary: minimal a33: store at n-1-i
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a37_reversed_store(DPGEN_IN const double* a, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) v[n - 1 - i] = a[i] * a[i];
}
