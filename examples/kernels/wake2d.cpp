// Kernels of the 2D wake flow behind a circular obstacle (examples/wake_flow_sol.py, the book's
// solver-in-the-loop notebook diffphys-code-sol.ipynb), loaded as PyTorch ops with
// dpgen_torch.load(); dpgen generates every adjoint (the semi-Lagrangian reads are
// data-dependent: scatter form).
//
// MAC grid of nx-by-ny cells of size h; x across the channel (closed walls at x = 0 and nx),
// y along it (open: inflow at the bottom, outflow at the top).
//   u on the x faces: (nx+1) per row, u[j*(nx+1) + i] on the west face of cell (i, j);
//     the wall faces i = 0 and i = nx are 0.
//   v on the y faces: ny+1 rows, v[j*nx + i] on the south face of cell (i, j); row 0 is the
//     inflow boundary, row ny the outflow boundary.
//   cell-centred fields (marker s, pressure p, divergence): s[j*nx + i].
// Beyond the open ends values are extrapolated with zero gradient (traces are clamped to the
// first and last rows); beyond the walls the tangential velocity v is 0 for the diffusion.
// (Integer clamps are conditionals: std::min on int locals is not in the generator's subset.)
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

// Explicit viscosity on u: u + c * (5-point Laplacian in cell units), c = nu dt / h^2.
DPGEN_KERNEL void wake_diffuse_u(DPGEN_IN const double* u, DPGEN_OUT double* u_out, int nx,
                                 int ny, double c) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (i == 0 || i == nx) {
        u_out[k] = 0.0;
        continue;
      }
      const int jn = j < ny - 1 ? j + 1 : j;
      const int js = j > 0 ? j - 1 : j;
      u_out[k] = u[k] + c * (u[j * (nx + 1) + i - 1] + u[j * (nx + 1) + i + 1] +
                             u[jn * (nx + 1) + i] + u[js * (nx + 1) + i] - 4.0 * u[k]);
    }
}

// Explicit viscosity on v (all ny+1 rows; the inflow rows are overwritten afterwards).
DPGEN_KERNEL void wake_diffuse_v(DPGEN_IN const double* v, DPGEN_OUT double* v_out, int nx,
                                 int ny, double c) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      const int jn = j < ny ? j + 1 : j;
      const int js = j > 0 ? j - 1 : j;
      const double mw = i > 0 ? 1.0 : 0.0, me = i < nx - 1 ? 1.0 : 0.0; // no slip at walls
      const int iw = i > 0 ? i - 1 : i, ie = i < nx - 1 ? i + 1 : i;
      v_out[k] = v[k] + c * (mw * v[j * nx + iw] + me * v[j * nx + ie] + v[jn * nx + i] +
                             v[js * nx + i] - 4.0 * v[k]);
    }
}

// Semi-Lagrangian transport of the marker: trace each cell centre back by dt * (centre
// velocity), clamp to the cell centres, interpolate bilinearly (dt_h = dt / h).
DPGEN_KERNEL void wake_advect_marker(DPGEN_IN const double* s, DPGEN_IN const double* u,
                                     DPGEN_IN const double* v, DPGEN_OUT double* s_out, int nx,
                                     int ny, double dt_h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double uc = 0.5 * (u[j * (nx + 1) + i] + u[j * (nx + 1) + i + 1]);
      const double vc = 0.5 * (v[j * nx + i] + v[(j + 1) * nx + i]);
      const double x = std::min(std::max(i - dt_h * uc, 0.0), nx - 1.0);
      const double y = std::min(std::max(j - dt_h * vc, 0.0), ny - 1.0);
      const int i0 = x < nx - 1 ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = y < ny - 1 ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 < nx - 1 ? i0 + 1 : i0;
      const int j1 = j0 < ny - 1 ? j0 + 1 : j0;
      const double fx = x - i0, fy = y - j0;
      s_out[j * nx + i] = (1.0 - fy) * ((1.0 - fx) * s[j0 * nx + i0] + fx * s[j0 * nx + i1]) +
                          fy * ((1.0 - fx) * s[j1 * nx + i0] + fx * s[j1 * nx + i1]);
    }
}

// Semi-Lagrangian self-advection of u on its face grid (face (i, j) at index coordinates
// (i, j)); the velocity at an x face is u there and the mean of the 4 nearest v faces.
DPGEN_KERNEL void wake_advect_u(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* u_out, int nx, int ny, double dt_h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (i == 0 || i == nx) {
        u_out[k] = 0.0;
        continue;
      }
      const double vf =
          0.25 * (v[j * nx + i - 1] + v[j * nx + i] + v[(j + 1) * nx + i - 1] + v[(j + 1) * nx + i]);
      const double x = std::min(std::max(i - dt_h * u[k], 0.0), 1.0 * nx);
      const double y = std::min(std::max(j - dt_h * vf, 0.0), ny - 1.0);
      const int i0 = x < nx ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = y < ny - 1 ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 + 1;
      const int j1 = j0 < ny - 1 ? j0 + 1 : j0;
      const double fx = x - i0, fy = y - j0;
      u_out[k] =
          (1.0 - fy) * ((1.0 - fx) * u[j0 * (nx + 1) + i0] + fx * u[j0 * (nx + 1) + i1]) +
          fy * ((1.0 - fx) * u[j1 * (nx + 1) + i0] + fx * u[j1 * (nx + 1) + i1]);
    }
}

// Semi-Lagrangian self-advection of v on its face grid (all ny+1 rows: the open ends are
// transported too); the velocity at a y face is v there and the mean of the 4 nearest u faces
// (rows clamped at the open ends).
DPGEN_KERNEL void wake_advect_v(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* v_out, int nx, int ny, double dt_h) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      const int ra = j < ny ? j : ny - 1; // the cell row above the face
      const int rb = j > 0 ? j - 1 : 0;   // and below it
      const double uf = 0.25 * (u[rb * (nx + 1) + i] + u[rb * (nx + 1) + i + 1] +
                                u[ra * (nx + 1) + i] + u[ra * (nx + 1) + i + 1]);
      const double x = std::min(std::max(i - dt_h * uf, 0.0), nx - 1.0);
      const double y = std::min(std::max(j - dt_h * v[k], 0.0), 1.0 * ny);
      const int i0 = x < nx - 1 ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = y < ny ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 < nx - 1 ? i0 + 1 : i0;
      const int j1 = j0 + 1;
      const double fx = x - i0, fy = y - j0;
      v_out[k] = (1.0 - fy) * ((1.0 - fx) * v[j0 * nx + i0] + fx * v[j0 * nx + i1]) +
                 fy * ((1.0 - fx) * v[j1 * nx + i0] + fx * v[j1 * nx + i1]);
    }
}

// div (u, v) per cell: (u_e - u_w + v_n - v_s) / h.
DPGEN_KERNEL void wake_divergence(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                  DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      div[j * nx + i] = (u[j * (nx + 1) + i + 1] - u[j * (nx + 1) + i] + v[(j + 1) * nx + i] -
                         v[j * nx + i]) / h;
}

// The pressure operator A p = -div(w grad p) with face weights: wx on the x faces, wy on the
// y faces (1 where the face is open between two fluid cells, 0 at walls, at the inflow row and
// at faces touching the obstacle; the outflow row ny has weight 1 and p = 0 beyond it, a
// Dirichlet condition that makes A positive definite). A solid cell (fluid = 0, all its faces
// weight 0) is an identity row. A is symmetric.
DPGEN_KERNEL void wake_pressure_operator(DPGEN_IN const double* p, DPGEN_IN const double* wx,
                                         DPGEN_IN const double* wy, DPGEN_IN const double* fluid,
                                         DPGEN_OUT double* out, int nx, int ny, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = j * nx + i;
      const int ie = i < nx - 1 ? i + 1 : i, iw = i > 0 ? i - 1 : i;
      const int jn = j < ny - 1 ? j + 1 : j, js = j > 0 ? j - 1 : j;
      const double mn = j < ny - 1 ? 1.0 : 0.0; // p = 0 beyond the outflow row
      double sum = wx[j * (nx + 1) + i + 1] * (p[c] - p[j * nx + ie]);
      sum += wx[j * (nx + 1) + i] * (p[c] - p[j * nx + iw]);
      sum += wy[(j + 1) * nx + i] * (p[c] - mn * p[jn * nx + i]);
      sum += wy[j * nx + i] * (p[c] - p[js * nx + i]);
      out[c] = sum * inv_h2 + (1.0 - fluid[c]) * p[c];
    }
}

// The projection's velocity update on the x faces: u - wx * dp/dx.
DPGEN_KERNEL void wake_subtract_gradient_u(DPGEN_IN const double* u, DPGEN_IN const double* p,
                                           DPGEN_IN const double* wx, DPGEN_OUT double* u_out,
                                           int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      const int ce = i < nx ? i : nx - 1, cw = i > 0 ? i - 1 : 0;
      u_out[k] = u[k] - wx[k] * (p[j * nx + ce] - p[j * nx + cw]) / h;
    }
}

// The projection's velocity update on the y faces: v - wy * dp/dy (p = 0 beyond the outflow).
DPGEN_KERNEL void wake_subtract_gradient_v(DPGEN_IN const double* v, DPGEN_IN const double* p,
                                           DPGEN_IN const double* wy, DPGEN_OUT double* v_out,
                                           int nx, int ny, double h) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      const int cn = j < ny ? j : ny - 1, cs = j > 0 ? j - 1 : 0;
      const double mn = j < ny ? 1.0 : 0.0;
      v_out[k] = v[k] - wy[k] * (mn * p[cn * nx + i] - p[cs * nx + i]) / h;
    }
}
