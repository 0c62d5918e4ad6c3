// Every violation of the output rules (checked on the lowered IR, check.cpp)
// is reported in one run, each at its store or read, across kernels: a value
// carried through an output, an in-place neighbour read, an output written
// by two nests that may overlap, and a non-affine output index. Nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void prefix(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  for (int i = 1; i < n; ++i)
    s[i] = s[i - 1] + a[i];
  // CHECK: every_output_error.cpp:[[@LINE-1]]:12: error: reads output 's': the adjoint has only the output's seed
}

DPGEN_KERNEL void smooth(DPGEN_INOUT double* u, int n) {
  for (int i = 1; i < n - 1; ++i)
    u[i] = 0.25 * u[i - 1] + 0.5 * u[i] + 0.25 * u[i + 1];
  // CHECK: every_output_error.cpp:[[@LINE-1]]:19: error: in-place array 'u' is read here
  // CHECK: every_output_error.cpp:[[@LINE-2]]:50: error: in-place array 'u' is read here
}

DPGEN_KERNEL void overlap(DPGEN_IN const double* a, DPGEN_OUT double* b, DPGEN_OUT double* c,
                          int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i];
  for (int i = 0; i < n; ++i)
    b[2 * i] = 2.0 * a[i];
  // CHECK-DAG: every_output_error.cpp:[[@LINE-1]]:5: error: output 'b' is also written on line 26 in another loop nest
  for (int i = 0; i < n; ++i)
    c[i * i] = a[i];
  // CHECK-DAG: every_output_error.cpp:[[@LINE-1]]:5: error: index of output 'c' multiplies loop counters
}
// CHECK: 5 errors generated.
