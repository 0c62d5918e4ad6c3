// Kernels of the 2D incompressible flow solver (dpgen/flow2d.hpp) on a closed
// MAC grid of nx-by-ny cells of size h: the marker s at cell centres (j*nx + i),
// u on the x faces ((nx+1) per row, u[j*(nx+1) + i] on the west face of cell
// (i, j)), v on the y faces (v[j*nx + i] on the south face). The wall faces
// (i = 0, nx for u; j = 0, ny for v) carry zero normal velocity. dpgen generates
// every adjoint; the semi-Lagrangian reads are data-dependent, so theirs are in
// scatter form.
#include "kernels.hpp"

#include <algorithm>
#include <cmath>

// (Integer clamps are written as conditionals: std::min on int locals is not
// supported by the generator yet.)

// Semi-Lagrangian transport of the marker, plus the inflow: trace each cell
// centre back by dt * (centre velocity), clamp to the cell centres (zero
// gradient at the walls), interpolate bilinearly:
//   s_out = s(x - dt u(x)) + inflow.   (dt_h = dt / h: distances in cells)
DPGEN_KERNEL void flow_advect_marker(DPGEN_IN const double* s, DPGEN_IN const double* u,
                                     DPGEN_IN const double* v, DPGEN_IN const double* inflow,
                                     DPGEN_OUT double* s_out, int nx, int ny, double dt_h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double uc = 0.5 * (u[j * (nx + 1) + i] + u[j * (nx + 1) + i + 1]);
      const double vc = 0.5 * (v[j * nx + i] + v[(j + 1) * nx + i]);
      const double x = std::min(std::max(i - dt_h * uc, 0.0), nx - 1.0);
      const double y = std::min(std::max(j - dt_h * vc, 0.0), ny - 1.0);
      const int i0 = static_cast<int>(std::floor(x));
      const int j0 = static_cast<int>(std::floor(y));
      const int i1 = i0 < nx - 1 ? i0 + 1 : i0;
      const int j1 = j0 < ny - 1 ? j0 + 1 : j0;
      const double fx = x - i0, fy = y - j0;
      s_out[j * nx + i] = (1.0 - fy) * ((1.0 - fx) * s[j0 * nx + i0] + fx * s[j0 * nx + i1]) +
                          fy * ((1.0 - fx) * s[j1 * nx + i0] + fx * s[j1 * nx + i1]) +
                          inflow[j * nx + i];
    }
}

// Semi-Lagrangian self-advection of u on its own (nx+1)-by-ny face grid; the
// velocity at an x face is u there and the mean of the 4 nearest v faces.
DPGEN_KERNEL void flow_advect_u(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* u_out, int nx, int ny, double dt_h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (i == 0 || i == nx) {
        u_out[k] = 0.0;
        continue;
      }
      const double vf = 0.25 * (v[j * nx + i - 1] + v[j * nx + i] + v[(j + 1) * nx + i - 1] +
                                v[(j + 1) * nx + i]);
      const double x = std::min(std::max(i - dt_h * u[k], 0.0), 1.0 * nx);
      const double y = std::min(std::max(j - dt_h * vf, 0.0), ny - 1.0);
      const int i0 = x < nx ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = static_cast<int>(std::floor(y));
      const int j1 = j0 < ny - 1 ? j0 + 1 : j0;
      const double fx = x - i0, fy = y - j0;
      u_out[k] =
          (1.0 - fy) * ((1.0 - fx) * u[j0 * (nx + 1) + i0] + fx * u[j0 * (nx + 1) + i0 + 1]) +
          fy * ((1.0 - fx) * u[j1 * (nx + 1) + i0] + fx * u[j1 * (nx + 1) + i0 + 1]);
    }
}

// div u per cell: (u_e - u_w + v_n - v_s) / h.
DPGEN_KERNEL void flow_divergence(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                  DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      div[j * nx + i] =
          (u[j * (nx + 1) + i + 1] - u[j * (nx + 1) + i] + v[(j + 1) * nx + i] - v[j * nx + i]) / h;
}

// The projection's velocity update: u -= dp/dx on the interior x faces.
// (One kernel per component: dpgen wants one loop nest per kernel.)
DPGEN_KERNEL void flow_subtract_gradient_u(DPGEN_IN const double* u, DPGEN_IN const double* p,
                                           DPGEN_OUT double* u_out, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (i == 0 || i == nx) {
        u_out[k] = 0.0;
        continue;
      }
      u_out[k] = u[k] - (p[j * nx + i] - p[j * nx + i - 1]) / h;
    }
}

// v -= dp/dy on the interior y faces.
DPGEN_KERNEL void flow_subtract_gradient_v(DPGEN_IN const double* v, DPGEN_IN const double* p,
                                           DPGEN_OUT double* v_out, int nx, int ny, double h) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (j == 0 || j == ny) {
        v_out[k] = 0.0;
        continue;
      }
      v_out[k] = v[k] - (p[k] - p[k - nx]) / h;
    }
}

// Semi-Lagrangian self-advection of v on its nx-by-(ny+1) face grid.
DPGEN_KERNEL void flow_advect_v(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* v_out, int nx, int ny, double dt_h) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (j == 0 || j == ny) {
        v_out[k] = 0.0;
        continue;
      }
      const double uf = 0.25 * (u[(j - 1) * (nx + 1) + i] + u[(j - 1) * (nx + 1) + i + 1] +
                                u[j * (nx + 1) + i] + u[j * (nx + 1) + i + 1]);
      const double x = std::min(std::max(i - dt_h * uf, 0.0), nx - 1.0);
      const double y = std::min(std::max(j - dt_h * v[k], 0.0), 1.0 * ny);
      const int i0 = static_cast<int>(std::floor(x));
      const int j0 = y < ny ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 < nx - 1 ? i0 + 1 : i0;
      const double fx = x - i0, fy = y - j0;
      v_out[k] = (1.0 - fy) * ((1.0 - fx) * v[j0 * nx + i0] + fx * v[j0 * nx + i1]) +
                 fy * ((1.0 - fx) * v[(j0 + 1) * nx + i0] + fx * v[(j0 + 1) * nx + i1]);
    }
}

// Boussinesq buoyancy: v += dt_b * (marker averaged onto the y face), with
// dt_b = dt * buoyancy coefficient.
DPGEN_KERNEL void flow_buoyancy(DPGEN_IN const double* v, DPGEN_IN const double* s,
                                DPGEN_OUT double* v_out, int nx, int ny, double dt_b) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (j == 0 || j == ny) {
        v_out[k] = 0.0;
        continue;
      }
      v_out[k] = v[k] + dt_b * 0.5 * (s[k - nx] + s[k]);
    }
}

// -div(k grad p) with closed walls (no flux through them; the constants are its
// null space): the pressure Poisson operator, k = 1 for a plain projection (a
// LevelOperator of dpgen/multigrid.hpp).
DPGEN_KERNEL void flow_pressure_operator(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                         DPGEN_OUT double* out, int nx, int ny, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = j * nx + i;
      double sum = i < nx - 1 ? 0.5 * (k[c] + k[c + 1]) * (p[c] - p[c + 1]) : 0.0;
      sum += i > 0 ? 0.5 * (k[c] + k[c - 1]) * (p[c] - p[c - 1]) : 0.0;
      sum += j < ny - 1 ? 0.5 * (k[c] + k[c + nx]) * (p[c] - p[c + nx]) : 0.0;
      sum += j > 0 ? 0.5 * (k[c] + k[c - nx]) * (p[c] - p[c - nx]) : 0.0;
      out[c] = sum * inv_h2;
    }
}

// The MacCormack correction of the marker transport (Selle et al. 2008, as PhiFlow's
// advect.mac_cormack): with s_sl = s traced back (flow_advect_marker, +dt, no inflow) and
// s_rev = s_sl traced forward (the same kernel with -dt), the corrected value
//   s_sl + (s - s_rev) / 2
// is clamped to the range of the 4 cells the backward trace interpolates between, so no new
// extremum appears; then the inflow is added.
DPGEN_KERNEL void flow_maccormack_marker(DPGEN_IN const double* s, DPGEN_IN const double* s_sl,
                                         DPGEN_IN const double* s_rev, DPGEN_IN const double* u,
                                         DPGEN_IN const double* v, DPGEN_IN const double* inflow,
                                         DPGEN_OUT double* s_out, int nx, int ny, double dt_h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      const double uc = 0.5 * (u[j * (nx + 1) + i] + u[j * (nx + 1) + i + 1]);
      const double vc = 0.5 * (v[j * nx + i] + v[(j + 1) * nx + i]);
      const double x = std::min(std::max(i - dt_h * uc, 0.0), nx - 1.0);
      const double y = std::min(std::max(j - dt_h * vc, 0.0), ny - 1.0);
      const int i0 = static_cast<int>(std::floor(x));
      const int j0 = static_cast<int>(std::floor(y));
      const int i1 = i0 < nx - 1 ? i0 + 1 : i0;
      const int j1 = j0 < ny - 1 ? j0 + 1 : j0;
      const double a = s[j0 * nx + i0], b = s[j0 * nx + i1];
      const double c = s[j1 * nx + i0], d = s[j1 * nx + i1];
      const double lo = std::min(std::min(a, b), std::min(c, d));
      const double hi = std::max(std::max(a, b), std::max(c, d));
      const double corrected = s_sl[k] + 0.5 * (s[k] - s_rev[k]);
      s_out[k] = std::min(std::max(corrected, lo), hi) + inflow[k];
    }
}
