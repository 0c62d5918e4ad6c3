// A forward kernel with an OpenMP pragma, parsed with -fopenmp: the pragma's
// loop is the kernel's loop.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc -fopenmp
// RUN: FileCheck %s --input-file %t/openmp_pragma_adjoint.cpp
// CHECK: void scale_adjoint(const double* a, double* a_adj, const double* out_adj, int n, double s) {
// CHECK: a_adj[c_i] += acc;
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void scale(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double s) {
#pragma omp parallel for
  for (int i = 0; i < n; ++i)
    out[i] = s * a[i];
}
