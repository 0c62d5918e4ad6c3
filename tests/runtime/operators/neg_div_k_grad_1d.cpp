// -d/dx(k dp/dx), Dirichlet: the ghost values are read only inside the
// conditional expressions' arms, so the adjoint never touches p[-1] or p[n].
#include "operators.hpp"

DPGEN_KERNEL void neg_div_k_grad_1d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                    DPGEN_OUT double* out, int n, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int i = 0; i < n; ++i) {
    const double left = i > 0 ? p[i - 1] : 0.0;
    const double right = i < n - 1 ? p[i + 1] : 0.0;
    out[i] = (k[i] * (p[i] - left) + k[i + 1] * (p[i] - right)) * inv_h2;
  }
}
