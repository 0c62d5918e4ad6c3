// Declarations of the test kernels (forward versions); one file per kernel.
#pragma once

#include "dpgen/annotate.hpp"

DPGEN_KERNEL void burgers_step(DPGEN_IN const double* u, DPGEN_OUT double* u_next, int n,
                               double dt, double dx, double nu);
DPGEN_KERNEL void varcoef_laplacian2d(DPGEN_IN const double* kc, DPGEN_IN const double* p,
                                      DPGEN_OUT double* out, int nx, int ny, double h);
DPGEN_KERNEL void laplacian3d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny,
                              int nz, double h);
DPGEN_KERNEL void mac_divergence2d(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                   DPGEN_OUT double* div, int nx, int ny, double h);
DPGEN_KERNEL void gradient2d(DPGEN_IN const double* p, DPGEN_OUT double* gx,
                             DPGEN_OUT double* gy, int nx, int ny, double h);
DPGEN_KERNEL void smooth_relax_f(DPGEN_IN const float* a, DPGEN_IN const float* b,
                                 DPGEN_OUT float* out, int n, float rate);
DPGEN_KERNEL void pointwise_math(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                 DPGEN_OUT double* out, int n);
DPGEN_KERNEL void semi_lagrangian(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                                  DPGEN_OUT double* q_next, int n, double dt, double dx);
DPGEN_KERNEL void scaled_rows(DPGEN_IN const double* a, DPGEN_IN const double* c,
                              DPGEN_IN const double* nu, const double* mask, DPGEN_OUT double* out,
                              int nx, int ny);
DPGEN_KERNEL void minmod_slope(DPGEN_IN const double* q, DPGEN_OUT double* slope, int n,
                               double dx);
DPGEN_KERNEL void edge_cases(DPGEN_IN const double* a, DPGEN_IN const double* b,
                             DPGEN_OUT double* out, DPGEN_OUT double* ends, int n, double s);
DPGEN_KERNEL void strided(DPGEN_IN const double* a, DPGEN_OUT double* out, int n);
DPGEN_KERNEL void clipped_sample(DPGEN_IN const double* q, DPGEN_IN const double* a,
                                 const double* mask, DPGEN_OUT double* out,
                                 DPGEN_OUT double* masked, int n);
DPGEN_KERNEL void leading_dim(DPGEN_IN const double* a, DPGEN_OUT double* b, const int* xmin,
                              const int* xmax, int ny, int ld);
DPGEN_KERNEL void fixed_rows(DPGEN_IN const double (*a)[8], DPGEN_OUT double b[][8], int n);
DPGEN_KERNEL void restrict_full_weighting(DPGEN_IN const double* fine, DPGEN_OUT double* coarse,
                                          int nf);
DPGEN_KERNEL void every_third(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int first);
DPGEN_KERNEL void clamped_neighbour(DPGEN_IN const double* a, DPGEN_OUT double* out, int n);
DPGEN_KERNEL void prolong_rows(DPGEN_IN const double* c, DPGEN_OUT double* f, int nx, int ncy);
DPGEN_KERNEL void react_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* rate, int n,
                                double dt);
DPGEN_KERNEL void relax_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* target, int n,
                                double w);
DPGEN_KERNEL void special_math(DPGEN_IN const double* a, DPGEN_IN const double* b,
                               DPGEN_IN const double* c, DPGEN_OUT double* out, int n);
DPGEN_KERNEL void special_math_f(DPGEN_IN const float* a, DPGEN_IN const float* b,
                                 DPGEN_IN const float* c, DPGEN_OUT float* out, int n);
