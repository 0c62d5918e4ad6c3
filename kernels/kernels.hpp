// Declarations of the kernels shipped in kernels/ (forward versions).
// Their adjoints are declared in the generated <stem>_adjoint.hpp headers.
#pragma once

#include "dpgen/annotate.hpp"

DPGEN_KERNEL void upwind_step(DPGEN_IN const double* d, DPGEN_IN const double* u,
                              DPGEN_OUT double* d_next, int n, double dt,
                              double dx);

DPGEN_KERNEL void divergence2d(DPGEN_IN const double* u, DPGEN_IN const double* v,
                               DPGEN_OUT double* div, int nx, int ny, double h);

DPGEN_KERNEL void laplacian2d(DPGEN_IN const double* a, DPGEN_OUT double* out,
                              int nx, int ny, double h);

// Multigrid transfers (multigrid_transfer.cpp), used by dpgen/solvers/multigrid.hpp.
// Bilinear prolongation along x: coarse nxc-by-ny -> fine 2nxc-by-ny. Ghost
// weights per wall: periodic (self 0, wrap 1), Neumann (1, 0), Dirichlet (-1, 0).
DPGEN_KERNEL void mg_prolong_x(DPGEN_IN const double* c, DPGEN_OUT double* f, int nxc, int ny,
                               double west_self, double west_wrap, double east_self,
                               double east_wrap);
// Bilinear prolongation along y: 2nxc-by-nyc -> 2nxc-by-2nyc.
DPGEN_KERNEL void mg_prolong_y(DPGEN_IN const double* c, DPGEN_OUT double* f, int nxc, int nyc,
                               double south_self, double south_wrap, double north_self,
                               double north_wrap);
// Coefficient coarsening: mean of the 2x2 fine cells of each coarse cell.
DPGEN_KERNEL void mg_average_2x2(DPGEN_IN const double* f, DPGEN_OUT double* c, int nxc, int nyc);

// The 2D flow solver's kernels (flow2d.cpp, used by dpgen/solvers/flow2d.hpp): MAC grid,
// marker s (nx*ny), u ((nx+1)*ny), v (nx*(ny+1)); dt_h = dt / h; px, py: 1 where
// an axis is periodic (face nx / row ny is then a copy of face / row 0), 0 closed.
DPGEN_KERNEL void flow_advect_marker(DPGEN_IN const double* s, DPGEN_IN const double* u,
                                     DPGEN_IN const double* v, DPGEN_IN const double* inflow,
                                     DPGEN_OUT double* s_out, int nx, int ny, double dt_h, int px,
                                     int py);
// zt: 1 = the tangential velocity is 0 beyond a closed wall (ghost faces), 0 = clamped.
DPGEN_KERNEL void flow_advect_u(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* u_out, int nx, int ny, double dt_h, int px,
                                int py, int zt);
DPGEN_KERNEL void flow_advect_v(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                DPGEN_OUT double* v_out, int nx, int ny, double dt_h, int px,
                                int py, int zt);
DPGEN_KERNEL void flow_buoyancy(DPGEN_IN const double* v, DPGEN_IN const double* s,
                                DPGEN_IN const double* fy, DPGEN_OUT double* v_out, int nx,
                                int ny, double dt_b, double dt, int py);
DPGEN_KERNEL void flow_force_u(DPGEN_IN const double* u, DPGEN_IN const double* fx,
                               DPGEN_OUT double* u_out, int nx, int ny, double dt, int px);
DPGEN_KERNEL void flow_divergence(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                  DPGEN_OUT double* div, int nx, int ny, double h, int px,
                                  int py);
DPGEN_KERNEL void flow_pressure_operator(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                         DPGEN_OUT double* out, int nx, int ny, double h,
                                         double ox, double oy);
DPGEN_KERNEL void flow_subtract_gradient_u(DPGEN_IN const double* u, DPGEN_IN const double* p,
                                           DPGEN_OUT double* u_out, int nx, int ny, double h,
                                           int px);
DPGEN_KERNEL void flow_subtract_gradient_v(DPGEN_IN const double* v, DPGEN_IN const double* p,
                                           DPGEN_OUT double* v_out, int nx, int ny, double h,
                                           int py);
DPGEN_KERNEL void flow_maccormack_marker(DPGEN_IN const double* s, DPGEN_IN const double* s_sl,
                                         DPGEN_IN const double* s_rev, DPGEN_IN const double* u,
                                         DPGEN_IN const double* v, DPGEN_IN const double* inflow,
                                         DPGEN_OUT double* s_out, int nx, int ny, double dt_h,
                                         int px, int py);
