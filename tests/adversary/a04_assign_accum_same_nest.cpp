// adversary: = then += into the same element in one iteration, plus a loss reduction
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a04_assign_accum_same_nest(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                             DPGEN_OUT double* loss, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i];
    u[i] += a[i] * a[i];
    loss[0] += a[i] * a[i] * a[i];
  }
}
