// Subdomain ("halo") kernels: the forward kernels of the distributed runs. Every array is one
// rank's block of a field padded with one halo cell on each side in every dimension, x fastest:
// 1D arrays hold n + 2 values (cell i of the block at index i + 1), 2D arrays (nx + 2)(ny + 2),
// 3D arrays (nx + 2)(ny + 2)(nz + 2). The loops run over the block's own cells only and read the
// halo cells as neighbours, so a kernel needs no periodic wrap and no knowledge of the
// decomposition: the halo exchange (dpgen/mpi/halo.hpp) fills the halos before it runs, and the
// reverse exchange returns the adjoints its generated adjoint leaves in the halos. Outputs are
// written on the block's cells only; their halo cells are left untouched.
#pragma once

#include "dpgen/annotate.hpp"

/// First-order upwind step (seed text eq. 17) on a block of n cells:
///   d_next[i] = d[i] - dt (min(u[i]/dx, 0) (d[i+1] - d[i]) + max(u[i]/dx, 0) (d[i] - d[i-1])).
DPGEN_KERNEL void upwind_step_halo(DPGEN_IN const double* d, DPGEN_IN const double* u,
                                   DPGEN_OUT double* d_next, int n, double dt, double dx);

/// -div(k grad p) with face coefficients (k[c] + k[m]) / 2, on an nx-by-ny block.
DPGEN_KERNEL void neg_div_k_grad_halo2d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                        DPGEN_OUT double* out, int nx, int ny, double h);

/// -Laplacian, 7-point, on a block given by its padded extents px = nx + 2, py = ny + 2, pz.
DPGEN_KERNEL void neg_laplacian_halo3d(DPGEN_IN const double* p, DPGEN_OUT double* out, int px,
                                       int py, int pz, double h);

/// MAC grid (u on west faces, v on south faces of each cell): the divergence of a block,
///   div = (u[east] - u + v[north] - v) / h.
DPGEN_KERNEL void mac_divergence_halo(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                      DPGEN_OUT double* div, int nx, int ny, double h);

/// -Laplacian, 5-point, on an nx-by-ny block (the pressure Poisson operator).
DPGEN_KERNEL void neg_laplacian_halo2d(DPGEN_IN const double* p, DPGEN_OUT double* out, int nx,
                                       int ny, double h);

/// MAC grid: (u, v) - grad p on a block; each face takes the difference of the cells it
/// separates (the west and south neighbours are halo cells at the block's edge).
DPGEN_KERNEL void mac_subtract_gradient_halo(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                             DPGEN_IN const double* p, DPGEN_OUT double* u_out,
                                             DPGEN_OUT double* v_out, int nx, int ny, double h);
