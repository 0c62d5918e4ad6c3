// adversary: float accumulator of a double product
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_float_double_mix(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  float s = 0.0f;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = 2.0 * s;
}
