// adversary: conditional second store under an index branch; store at n-1-i
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a33_cond_store_index(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i];
    if (i > 0) u[i] = a[i - 1] * u[i];
    v[n - 1 - i] = a[i] * a[i];
  }
}
