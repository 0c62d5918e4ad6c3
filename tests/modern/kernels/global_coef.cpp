// corpus: form=global expect=accept
// Globals as C-style codes keep them: a const global and a non-const one
// only read (constants), a global field pointer and a global coefficient
// table marked DPGEN_IN (differentiated: the adjoint header declares
// `extern double* g_kappa_adj;` and `extern double* g_stencil_adj;`, which the
// caller points at adjoint storage; the adjoint accumulates into them).
#include "dpgen/annotate.hpp"

const double g_cfl = 0.4;
double g_dx = 0.5;
DPGEN_IN double* g_kappa = nullptr;
DPGEN_IN double g_stencil[3] = {0.25, 0.5, 0.25};

DPGEN_KERNEL void varcoef_smooth(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double c = g_cfl / (g_dx * g_dx);
  for (int i = 1; i < n - 1; ++i) {
    double s = 0.0;
    for (int m = 0; m < 3; ++m)
      s += g_stencil[m] * u[i - 1 + m];
    out[i] = u[i] + c * g_kappa[i] * (s - u[i]);
  }
}
