// Per-cell quotients and square roots that the adjoint needs at neighbouring
// cells, as transport and diffusion codes compute them: once per cell of the
// forward, and at up to three cells of each adjoint cell. The generated
// adjoint computes each of them once per cell of a strip (the pass `share`):
// a speed read at i - 1 and i + 1 only; a float conductivity sqrt on a flat
// row-major grid, shared along rows (i - 1, i, i + 1) but not across them; a
// 9-point average weighted by a per-cell reciprocal, shared along each of the
// rows j - 1, j, j + 1; a quotient in the arm of a conditional, which is not
// shared (the source computes it only where the condition holds).
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void centred_speed(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                DPGEN_OUT double* qn, int n, double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double s = u[i] / (dx + std::fabs(u[i])); // a bounded speed
    qn[i] = q[i] - s * (q[i + 1] - q[i - 1]);
  }
}

DPGEN_KERNEL void sqrt_conductivity2d(DPGEN_IN const float* phi, DPGEN_OUT float* out, int nx,
                                      int ny, float dt) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int c = j * nx + i;
      const float kc = std::sqrt(1.0f + std::fabs(phi[c]));
      const float ke = std::sqrt(1.0f + std::fabs(phi[c + 1]));
      const float kw = std::sqrt(1.0f + std::fabs(phi[c - 1]));
      const float kn = std::sqrt(1.0f + std::fabs(phi[c + nx]));
      const float ks = std::sqrt(1.0f + std::fabs(phi[c - nx]));
      out[c] = phi[c] + dt * ((kc + ke) * (phi[c + 1] - phi[c]) - (kc + kw) * (phi[c] - phi[c - 1]) +
                              (kc + kn) * (phi[c + nx] - phi[c]) - (kc + ks) * (phi[c] - phi[c - nx]));
    }
}

DPGEN_KERNEL void ninepoint_weights(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const double w = 1.0 / (2.0 + std::fabs(a[j * nx + i]));
      b[j * nx + i] = w * (a[(j - 1) * nx + i - 1] + a[(j - 1) * nx + i] + a[(j - 1) * nx + i + 1] +
                           a[j * nx + i - 1] + a[j * nx + i + 1] + a[(j + 1) * nx + i - 1] +
                           a[(j + 1) * nx + i] + a[(j + 1) * nx + i + 1]);
    }
}

DPGEN_KERNEL void ratio_in_branch(DPGEN_IN const double* q, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double a = q[i] - q[i - 1];
    out[i] = a > 0.0 ? a / (1.0 + std::fabs(q[i + 1])) : 0.5 * a;
  }
}
