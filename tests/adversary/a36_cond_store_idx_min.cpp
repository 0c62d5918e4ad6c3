// adversary: minimal a33: second store under if (i > 0) reading the first
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a36_cond_store_idx_min(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i];
    if (i > 0) u[i] = a[i - 1] * u[i];
  }
}
