// adversary: accumulator whose init reads an input
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_init_reads_input(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                          DPGEN_OUT double* out, int n) {
  double s = a[0] * b[0];
  for (int i = 1; i < n; ++i) s += a[i] * a[i - 1];
  out[0] = s * a[0];
}
