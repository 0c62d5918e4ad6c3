// adversary: out[i] and out[i+1] both stored per iteration: iteration i+1 overwrites
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a12_overlap_iters(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i + 1 < n; ++i) {
    u[i] = a[i] * a[i];
    u[i + 1] = a[i] * 3.0;
  }
}
