// adversary: accumulates the output it just stored
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_readback_output(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                         DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    s += u[i] * a[i];
  }
  out[0] = s * s;
}
