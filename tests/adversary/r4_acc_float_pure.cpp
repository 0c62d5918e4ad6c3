// adversary: float kernel: two float accumulators with -=
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_float_pure(DPGEN_IN const float* a, DPGEN_IN const float* b, DPGEN_OUT float* out, int n) {
  float s = 0.0f, t = 1.0f;
  for (int i = 0; i < n; ++i) { s += a[i] * b[i]; t -= b[i] * b[i]; }
  out[0] = s * t;
}
