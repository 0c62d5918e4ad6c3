// corpus: form=return expect=accept
// Writes an output array and returns a value: the residual r = f - A u of a
// 1D Poisson operator, and its squared norm (what a solver's convergence
// test reads back). Two outputs: r (array) and the returned value.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL double residual(DPGEN_IN const double* u, DPGEN_IN const double* f,
                             DPGEN_OUT double* r, int n, double inv_h2) {
  double rr = 0.0;
  for (int i = 1; i < n - 1; ++i) {
    r[i] = f[i] - inv_h2 * (2.0 * u[i] - u[i - 1] - u[i + 1]);
    rr += r[i] * r[i];
  }
  return rr;
}
