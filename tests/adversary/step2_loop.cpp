#include "dpgen/annotate.hpp"
DPGEN_KERNEL void step2_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i + 1 < n; i += 2)
    out[i / 2] = a[i] * a[i + 1];
}
