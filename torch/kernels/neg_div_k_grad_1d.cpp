// -d/dx(k dp/dx) on n cells with Dirichlet walls: k holds the n + 1 face coefficients. The
// operator of the differentiable solve op dpgen::diffusion_solve (solver_ops.cpp), and an op
// of its own. (The same kernel as tests/runtime/operators/neg_div_k_grad_1d.cpp.)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void neg_div_k_grad_1d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                    DPGEN_OUT double* out, int n, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int i = 0; i < n; ++i) {
    const double left = i > 0 ? p[i - 1] : 0.0;
    const double right = i < n - 1 ? p[i + 1] : 0.0;
    out[i] = (k[i] * (p[i] - left) + k[i + 1] * (p[i] - right)) * inv_h2;
  }
}
