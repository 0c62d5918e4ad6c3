#include "dpgen/annotate.hpp"
DPGEN_KERNEL void modulo_wrap(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[(i + 1) % n] * a[(i + n - 1) % n] - a[i];
}
