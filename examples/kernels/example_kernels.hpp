// Kernels of the examples (forward versions). Their adjoints are generated at
// build time into <stem>_adjoint.hpp.
#pragma once

#include "dpgen/annotate.hpp"

// Periodic MAC grid, nx*ny cells of size h; u[j*nx+i] is the x-velocity on the
// west face of cell (i, j), v[j*nx+i] the y-velocity on its south face.
DPGEN_KERNEL void mac_divergence_periodic(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                          DPGEN_OUT double* div, int nx, int ny, double h);
DPGEN_KERNEL void neg_laplacian_periodic(DPGEN_IN const double* p, DPGEN_OUT double* out,
                                         int nx, int ny, double h);
DPGEN_KERNEL void mac_subtract_gradient(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                        DPGEN_IN const double* p, DPGEN_OUT double* u_out,
                                        DPGEN_OUT double* v_out, int nx, int ny, double h);

// 1D periodic Burgers pieces (the Physics-based Deep Learning book's setup).
DPGEN_KERNEL void diffuse_explicit(DPGEN_IN const double* u, DPGEN_OUT double* u_out, int n,
                                   double dt, double nu, double dx);
DPGEN_KERNEL void advect_self_semi_lagrangian(DPGEN_IN const double* u, DPGEN_OUT double* u_out,
                                              int n, double dt, double dx);
