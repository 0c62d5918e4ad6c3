// Per-cell quotients and square roots that the adjoint needs at neighbouring
// cells, as transport and diffusion codes compute them: once per cell of the
// forward, and at up to three cells of each adjoint cell. The generated
// adjoint computes each of them once per cell of a strip (the pass `share`):
// a speed read at i - 1 and i + 1 only; a float conductivity sqrt on a flat
// row-major grid, shared along rows (i - 1, i, i + 1) but not across them; a
// 9-point average weighted by a per-cell reciprocal, shared along each of the
// rows j - 1, j, j + 1; a quotient in the arm of a conditional, which is not
// shared (the source computes it only where the condition holds). Codes that
// spell one quotient per neighbour (`u[i - 1] / dx`, `u[i] / dx`,
// `u[i + 1] / dx`, or weights read mirrored at n - 1 - i and n - 2 - i) get
// one buffer for all of them: each is the others at another iteration. A
// Gaussian weight exp(-q * q * c) at each neighbour is one buffer too (no sum
// takes its products, so it is shared).
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

// A flux-form upwind step as finite-volume codes write it: the face speeds
// from the cell speeds on each side, each cell speed spelled per neighbour.
DPGEN_KERNEL void flux_form_upwind(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                   DPGEN_OUT double* qn, int n, double dt, double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double cm = u[i - 1] / dx, c0 = u[i] / dx, cp = u[i + 1] / dx;
    const double ul = 0.5 * (cm + c0), ur = 0.5 * (c0 + cp);
    const double fl = ul > 0.0 ? ul * q[i - 1] : ul * q[i];
    const double fr = ur > 0.0 ? ur * q[i] : ur * q[i + 1];
    qn[i] = q[i] - dt * (fr - fl);
  }
}

// Weights read from a coefficient array stored in reverse order.
DPGEN_KERNEL void mirrored_weights(DPGEN_IN const double* q, const double* w, DPGEN_OUT double* out,
                                   int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double a = 1.0 / (1.0 + std::fabs(w[n - 1 - i]));
    const double b = 1.0 / (1.0 + std::fabs(w[n - 2 - i]));
    out[i] = a * q[i - 1] + b * q[i + 1];
  }
}

// A normalized Gaussian smoothing whose weights depend on the data, as kernel
// smoothers and bilateral filters write them: one exp per neighbour.
DPGEN_KERNEL void gaussian_neighbours(DPGEN_IN const double* q, DPGEN_OUT double* out, int n,
                                      double inv_two_s2) {
  for (int i = 1; i < n - 1; ++i) {
    const double gm = std::exp(-(q[i - 1] * q[i - 1]) * inv_two_s2);
    const double g0 = std::exp(-(q[i] * q[i]) * inv_two_s2);
    const double gp = std::exp(-(q[i + 1] * q[i + 1]) * inv_two_s2);
    out[i] = (gm * q[i - 1] + g0 * q[i] + gp * q[i + 1]) / (gm + g0 + gp);
  }
}
