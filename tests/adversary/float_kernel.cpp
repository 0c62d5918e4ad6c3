#include "dpgen/annotate.hpp"
DPGEN_KERNEL void float_kernel(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = 0.1 * a[i - 1] * a[i + 1] + a[i] / 3.0;
}
