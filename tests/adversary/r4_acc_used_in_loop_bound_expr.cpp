// adversary: accumulator read in a later loop together with a triangular bound
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_used_in_loop_bound_expr(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) e[i * n + j] = s * a[j] - a[i];
}
