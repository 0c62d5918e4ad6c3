// Assembles a right-hand side by accumulating into the output: a source
// term, then the discrete Laplacian, both with +=.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void rhs_accumulate(DPGEN_IN const double* u, DPGEN_IN const double* f,
                                 DPGEN_OUT double* rhs, int n, double inv_h2) {
  for (int i = 1; i < n - 1; ++i) {
    rhs[i] += f[i];
    rhs[i] += inv_h2 * (u[i - 1] - 2.0 * u[i] + u[i + 1]);
  }
}
