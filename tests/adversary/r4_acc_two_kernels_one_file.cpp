// adversary: two kernels with an accumulator s in one file
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_two_kernels_one_file_b(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 2.0;
  for (int i = 0; i < n; ++i) s += a[i];
  out[0] = s;
}
DPGEN_KERNEL void r4_acc_two_kernels_one_file(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s;
}
