// adversary: accumulator read inside its own loop (prefix sum)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_prefix_read_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    s += a[i];
    u[i] = s * s;
  }
}
