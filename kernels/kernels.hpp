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
