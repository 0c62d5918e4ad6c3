// adversary: index branches with continue, periodic wraps (read), periodic-wrapped store
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a26_index_branch_periodic(DPGEN_IN const double* u, DPGEN_OUT double* o, DPGEN_OUT double* p, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0 || i == n - 1) { o[i] = u[i] * u[i]; continue; }
    o[i] = u[i - 1] * u[i + 1];
  }
  for (int i = 0; i < n; ++i) {
    int ip = i == n - 1 ? 0 : i + 1;
    int im = i == 0 ? n - 1 : i - 1;
    p[ip] = u[im] * u[i] + u[ip];
  }
}
