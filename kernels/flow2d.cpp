// Kernels of the 2D incompressible flow solver (dpgen/solvers/flow2d.hpp) on a MAC grid of
// nx-by-ny cells of size h: the marker s at cell centres (j*nx + i), u on the x
// faces ((nx+1) per row, u[j*(nx+1) + i] on the west face of cell (i, j)), v on
// the y faces (v[j*nx + i] on the south face). dpgen generates every adjoint; the
// semi-Lagrangian reads are data-dependent, so theirs are in scatter form.
//
// Each axis is closed or periodic (px, py: 0 or 1).
//   closed:   the wall faces (i = 0, nx for u; j = 0, ny for v) carry zero normal
//             velocity; traces are clamped to the grid (zero gradient at walls).
//             The velocity's self-advection (flow_advect_u/v) clamps a trace's
//             tangential coordinate to the first and last face rows (zt = 0), or
//             (zt = 1) takes the tangential velocity beyond a closed wall as 0, half a
//             cell outside (the ghost values of PhiFlow's extrapolation.ZERO).
//   periodic: face nx of a u row is face 0 (row ny of v is row 0). The kernels
//             write it as a bit-identical copy of face 0 (same expression, same
//             reads) and never read it: it is there so that both layouts are the
//             same, and a state's copy faces have no influence on anything.
//             Traces wrap around (x - nx floor(x / nx): floor has zero
//             derivative, so the wrap does not change the gradient).
#include "kernels.hpp"

#include <algorithm>
#include <cmath>

// (Integer clamps are written as conditionals: std::min on int locals is not
// supported by the generator yet.)

// Semi-Lagrangian transport of the marker, plus the inflow: trace each cell
// centre back by dt * (centre velocity), clamp to the cell centres (closed) or
// wrap (periodic), interpolate bilinearly:
//   s_out = s(x - dt u(x)) + inflow.   (dt_h = dt / h: distances in cells)
DPGEN_KERNEL void flow_advect_marker(DPGEN_IN const double* s, DPGEN_IN const double* u,
                                     DPGEN_IN const double* v, DPGEN_IN const double* inflow,
                                     DPGEN_OUT double* s_out, int nx, int ny, double dt_h, int px,
                                     int py) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ie = i < nx - 1 ? i + 1 : (px != 0 ? 0 : nx); // east face (wrapped)
      const int jn = j < ny - 1 ? j + 1 : (py != 0 ? 0 : ny); // north face row (wrapped)
      const double uc = 0.5 * (u[j * (nx + 1) + i] + u[j * (nx + 1) + ie]);
      const double vc = 0.5 * (v[j * nx + i] + v[jn * nx + i]);
      const double xr = i - dt_h * uc, yr = j - dt_h * vc;
      const double x =
          px != 0 ? xr - nx * std::floor(xr / nx) : std::min(std::max(xr, 0.0), nx - 1.0);
      const double y =
          py != 0 ? yr - ny * std::floor(yr / ny) : std::min(std::max(yr, 0.0), ny - 1.0);
      // (x < nx also when x rounds to nx after the wrap: cell nx-1 with weight fx = 1.)
      const int i0 = x < nx - 1 ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = y < ny - 1 ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 < nx - 1 ? i0 + 1 : (px != 0 ? 0 : i0);
      const int j1 = j0 < ny - 1 ? j0 + 1 : (py != 0 ? 0 : j0);
      const double fx = x - i0, fy = y - j0;
      s_out[j * nx + i] = (1.0 - fy) * ((1.0 - fx) * s[j0 * nx + i0] + fx * s[j0 * nx + i1]) +
                          fy * ((1.0 - fx) * s[j1 * nx + i0] + fx * s[j1 * nx + i1]) +
                          inflow[j * nx + i];
    }
}

// Semi-Lagrangian self-advection of u on its own (nx+1)-by-ny face grid; the
// velocity at an x face is u there and the mean of the 4 nearest v faces. zt = 1
// (closed y walls): u is 0 on ghost rows -1 and ny, so a trace ending within half a
// cell of a wall (or beyond it) interpolates towards 0; zt = 0: the trace is clamped
// to rows 0 and ny-1. (The ghost rows are weights m0, m1 of 0 on rows read in range.)
DPGEN_KERNEL void flow_advect_u(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* u_out, int nx, int ny, double dt_h, int px,
                                int py, int zt) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (px == 0 && (i == 0 || i == nx)) {
        u_out[k] = 0.0;
        continue;
      }
      const int ce = i < nx ? i : 0;      // the cell east of the face; face nx is face 0
      const int cw = i > 0 ? i - 1 : nx - 1; // the cell west of it
      const int jn = j < ny - 1 ? j + 1 : (py != 0 ? 0 : ny);
      const double vf =
          0.25 * (v[j * nx + cw] + v[j * nx + ce] + v[jn * nx + cw] + v[jn * nx + ce]);
      const double xr = ce - dt_h * u[j * (nx + 1) + ce], yr = j - dt_h * vf;
      const double x =
          px != 0 ? xr - nx * std::floor(xr / nx) : std::min(std::max(xr, 0.0), 1.0 * nx);
      const double ylo = zt != 0 ? -1.0 : 0.0, yhi = zt != 0 ? 1.0 * ny : ny - 1.0;
      const double y =
          py != 0 ? yr - ny * std::floor(yr / ny) : std::min(std::max(yr, ylo), yhi);
      const int i0 = x < nx - 1 ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = y < ny - 1 ? static_cast<int>(std::floor(y)) : ny - 1; // -1 with zt
      const int i1 = i0 < nx - 1 ? i0 + 1 : (px != 0 ? 0 : nx);
      const int j1 = j0 < ny - 1 ? j0 + 1 : (py != 0 ? 0 : (zt != 0 ? ny : j0)); // ny: ghost
      const double fx = x - i0, fy = y - j0;
      const double m0 = j0 >= 0 ? 1.0 : 0.0, m1 = j1 < ny ? 1.0 : 0.0;
      const int r0 = j0 >= 0 ? j0 : 0, r1 = j1 < ny ? j1 : ny - 1;
      u_out[k] = (1.0 - fy) * m0 *
                     ((1.0 - fx) * u[r0 * (nx + 1) + i0] + fx * u[r0 * (nx + 1) + i1]) +
                 fy * m1 * ((1.0 - fx) * u[r1 * (nx + 1) + i0] + fx * u[r1 * (nx + 1) + i1]);
    }
}

// Semi-Lagrangian self-advection of v on its nx-by-(ny+1) face grid; zt as in
// flow_advect_u, for the ghost columns -1 and nx of closed x walls.
DPGEN_KERNEL void flow_advect_v(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* v_out, int nx, int ny, double dt_h, int px,
                                int py, int zt) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (py == 0 && (j == 0 || j == ny)) {
        v_out[k] = 0.0;
        continue;
      }
      const int cn = j < ny ? j : 0;      // the cell row north of the face; row ny is row 0
      const int cs = j > 0 ? j - 1 : ny - 1; // the row south of it
      const int ie = i < nx - 1 ? i + 1 : (px != 0 ? 0 : nx);
      const double uf = 0.25 * (u[cs * (nx + 1) + i] + u[cs * (nx + 1) + ie] +
                                u[cn * (nx + 1) + i] + u[cn * (nx + 1) + ie]);
      const double xr = i - dt_h * uf, yr = cn - dt_h * v[cn * nx + i];
      const double xlo = zt != 0 ? -1.0 : 0.0, xhi = zt != 0 ? 1.0 * nx : nx - 1.0;
      const double x =
          px != 0 ? xr - nx * std::floor(xr / nx) : std::min(std::max(xr, xlo), xhi);
      const double y =
          py != 0 ? yr - ny * std::floor(yr / ny) : std::min(std::max(yr, 0.0), 1.0 * ny);
      const int i0 = x < nx - 1 ? static_cast<int>(std::floor(x)) : nx - 1; // -1 with zt
      const int j0 = y < ny - 1 ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 < nx - 1 ? i0 + 1 : (px != 0 ? 0 : (zt != 0 ? nx : i0)); // nx: ghost
      const int j1 = j0 < ny - 1 ? j0 + 1 : (py != 0 ? 0 : ny);
      const double fx = x - i0, fy = y - j0;
      const double m0 = i0 >= 0 ? 1.0 : 0.0, m1 = i1 < nx ? 1.0 : 0.0;
      const int c0 = i0 >= 0 ? i0 : 0, c1 = i1 < nx ? i1 : nx - 1;
      v_out[k] = (1.0 - fy) * ((1.0 - fx) * m0 * v[j0 * nx + c0] + fx * m1 * v[j0 * nx + c1]) +
                 fy * ((1.0 - fx) * m0 * v[j1 * nx + c0] + fx * m1 * v[j1 * nx + c1]);
    }
}

// div u per cell: (u_e - u_w + v_n - v_s) / h (the east and north faces of the
// last column and row wrap to face 0 when periodic: copies are not read).
DPGEN_KERNEL void flow_divergence(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                  DPGEN_OUT double* div, int nx, int ny, double h, int px,
                                  int py) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ie = i < nx - 1 ? i + 1 : (px != 0 ? 0 : nx);
      const int jn = j < ny - 1 ? j + 1 : (py != 0 ? 0 : ny);
      div[j * nx + i] =
          (u[j * (nx + 1) + ie] - u[j * (nx + 1) + i] + v[jn * nx + i] - v[j * nx + i]) / h;
    }
}

// The projection's velocity update: u -= dp/dx on the x faces (closed: the
// walls stay zero; periodic: face nx is face 0 again).
// (One kernel per component: dpgen wants one loop nest per kernel.)
DPGEN_KERNEL void flow_subtract_gradient_u(DPGEN_IN const double* u, DPGEN_IN const double* p,
                                           DPGEN_OUT double* u_out, int nx, int ny, double h,
                                           int px) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (px == 0 && (i == 0 || i == nx)) {
        u_out[k] = 0.0;
        continue;
      }
      const int ce = i < nx ? i : 0;
      const int cw = i > 0 ? i - 1 : nx - 1;
      u_out[k] = u[j * (nx + 1) + ce] - (p[j * nx + ce] - p[j * nx + cw]) / h;
    }
}

// v -= dp/dy on the y faces.
DPGEN_KERNEL void flow_subtract_gradient_v(DPGEN_IN const double* v, DPGEN_IN const double* p,
                                           DPGEN_OUT double* v_out, int nx, int ny, double h,
                                           int py) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (py == 0 && (j == 0 || j == ny)) {
        v_out[k] = 0.0;
        continue;
      }
      const int cn = j < ny ? j : 0;
      const int cs = j > 0 ? j - 1 : ny - 1;
      v_out[k] = v[cn * nx + i] - (p[cn * nx + i] - p[cs * nx + i]) / h;
    }
}

// Boussinesq buoyancy and a body force on the y faces:
//   v += dt_b * (marker averaged onto the face) + dt * (fy averaged onto the face),
// with dt_b = dt * buoyancy coefficient and fy a force per unit mass at the cell
// centres.
DPGEN_KERNEL void flow_buoyancy(DPGEN_IN const double* v, DPGEN_IN const double* s,
                                DPGEN_IN const double* fy, DPGEN_OUT double* v_out, int nx,
                                int ny, double dt_b, double dt, int py) {
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (py == 0 && (j == 0 || j == ny)) {
        v_out[k] = 0.0;
        continue;
      }
      const int n = (j < ny ? j : 0) * nx + i;       // the cell north of the face
      const int so = (j > 0 ? j - 1 : ny - 1) * nx + i; // and south of it
      v_out[k] = v[n] + dt_b * 0.5 * (s[so] + s[n]) + dt * 0.5 * (fy[so] + fy[n]);
    }
}

// The body force on the x faces: u += dt * (fx averaged onto the face).
DPGEN_KERNEL void flow_force_u(DPGEN_IN const double* u, DPGEN_IN const double* fx,
                               DPGEN_OUT double* u_out, int nx, int ny, double dt, int px) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int k = j * (nx + 1) + i;
      if (px == 0 && (i == 0 || i == nx)) {
        u_out[k] = 0.0;
        continue;
      }
      const int ce = i < nx ? i : 0;
      const int cw = i > 0 ? i - 1 : nx - 1;
      u_out[k] = u[j * (nx + 1) + ce] + dt * 0.5 * (fx[j * nx + cw] + fx[j * nx + ce]);
    }
}

// -div(k grad p) with closed walls (no flux through them) or periodic axes; the
// constants are its null space either way: the pressure Poisson operator, k = 1
// for a plain projection (a LevelOperator of dpgen/solvers/multigrid.hpp, with px, py
// bound). ox, oy: 1 for periodic, 0 for closed (the weight of the wrapped face).
DPGEN_KERNEL void flow_pressure_operator(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                         DPGEN_OUT double* out, int nx, int ny, double h,
                                         double ox, double oy) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = j * nx + i;
      const int e = j * nx + (i < nx - 1 ? i + 1 : 0);
      const int w = j * nx + (i > 0 ? i - 1 : nx - 1);
      const int no = (j < ny - 1 ? j + 1 : 0) * nx + i;
      const int so = (j > 0 ? j - 1 : ny - 1) * nx + i;
      double sum = (i < nx - 1 ? 1.0 : ox) * 0.5 * (k[c] + k[e]) * (p[c] - p[e]);
      sum += (i > 0 ? 1.0 : ox) * 0.5 * (k[c] + k[w]) * (p[c] - p[w]);
      sum += (j < ny - 1 ? 1.0 : oy) * 0.5 * (k[c] + k[no]) * (p[c] - p[no]);
      sum += (j > 0 ? 1.0 : oy) * 0.5 * (k[c] + k[so]) * (p[c] - p[so]);
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
                                         DPGEN_OUT double* s_out, int nx, int ny, double dt_h,
                                         int px, int py) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      const int ie = i < nx - 1 ? i + 1 : (px != 0 ? 0 : nx);
      const int jn = j < ny - 1 ? j + 1 : (py != 0 ? 0 : ny);
      const double uc = 0.5 * (u[j * (nx + 1) + i] + u[j * (nx + 1) + ie]);
      const double vc = 0.5 * (v[j * nx + i] + v[jn * nx + i]);
      const double xr = i - dt_h * uc, yr = j - dt_h * vc;
      const double x =
          px != 0 ? xr - nx * std::floor(xr / nx) : std::min(std::max(xr, 0.0), nx - 1.0);
      const double y =
          py != 0 ? yr - ny * std::floor(yr / ny) : std::min(std::max(yr, 0.0), ny - 1.0);
      const int i0 = x < nx - 1 ? static_cast<int>(std::floor(x)) : nx - 1;
      const int j0 = y < ny - 1 ? static_cast<int>(std::floor(y)) : ny - 1;
      const int i1 = i0 < nx - 1 ? i0 + 1 : (px != 0 ? 0 : i0);
      const int j1 = j0 < ny - 1 ? j0 + 1 : (py != 0 ? 0 : j0);
      const double a = s[j0 * nx + i0], b = s[j0 * nx + i1];
      const double c = s[j1 * nx + i0], d = s[j1 * nx + i1];
      const double lo = std::min(std::min(a, b), std::min(c, d));
      const double hi = std::max(std::max(a, b), std::max(c, d));
      const double corrected = s_sl[k] + 0.5 * (s[k] - s_rev[k]);
      s_out[k] = std::min(std::max(corrected, lo), hi) + inflow[k];
    }
}
