// adversary: accumulator computed differently per arm, read after the if
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_arm_accum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 0.0;
  if (flag == 0) {
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) s += a[i];
  }
  out[0] = s * s + s;
}
