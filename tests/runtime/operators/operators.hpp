// Operators of the implicit-solve tests, as dpgen kernels: their adjoints
// with respect to the coefficient k (and p) are generated, not hand-written.
#pragma once

#include "dpgen/annotate.hpp"

// -d/dx(k dp/dx) on n cells with zero Dirichlet ghosts p[-1] = p[n] = 0; k on
// the n+1 faces. Symmetric positive definite for k > 0.
DPGEN_KERNEL void neg_div_k_grad_1d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                    DPGEN_OUT double* out, int n, double h);

// -div(k grad p) on a periodic nx-by-ny grid, k at cell centres averaged onto
// faces. Symmetric positive semi-definite, the constants as null space.
DPGEN_KERNEL void neg_div_k_grad_periodic2d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                            DPGEN_OUT double* out, int nx, int ny, double h);

// -div(k grad p) on an nx-by-ny grid with a wall on every side; `west` ... `north`
// weigh the wall faces: 0 = Neumann (no flux), 2 = Dirichlet (p = 0 on the face).
// Symmetric; positive definite with a Dirichlet side, else the constants as null space.
DPGEN_KERNEL void neg_div_k_grad_walls2d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                         DPGEN_OUT double* out, int nx, int ny, double h,
                                         double west, double east, double south, double north);
