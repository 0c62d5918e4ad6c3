// adversary: accumulator initialised from a double parameter
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_bias_param(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double bias) {
  double s = bias;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s;
}
