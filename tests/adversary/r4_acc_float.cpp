// adversary: float accumulator
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_float(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float s = 0.0f;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s + 0.5f * s;
}
