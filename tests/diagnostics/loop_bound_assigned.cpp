// A loop bound that the loop's body assigns: C tests the condition before every iteration,
// so the count changes as the loop runs. Refused (the kernel-level form was accepted with
// the bound's first value, a wrong adjoint, before 2026-12-01; the loop-level form gave a
// parallel forward and tangent that did not compile, then for a commit the same wrong
// values). Every error of the file is reported in one run, and no file is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void kernel_level(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int m = n;
  for (int i = 0; i < m; ++i) {
    // CHECK: loop_bound_assigned.cpp:[[@LINE-1]]:19: error: the condition of loop 'i' reads 'm', which the loop's body assigns: dpgen needs a loop's bounds fixed before it runs; give the new value a variable of its own, or set 'm' before the loop [dpgen-loop]
    b[i] = a[i] * a[i];
    m = 5;
  }
}

DPGEN_KERNEL void row_loop(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    int m = nx;
    for (int i = 0; i < m; ++i) {
      // CHECK: loop_bound_assigned.cpp:[[@LINE-1]]:21: error: the condition of loop 'i' reads 'm'
      b[j * nx + i] = a[j * nx + i];
      if (i == 3)
        m = 5 + j % 2;
    }
  }
}

DPGEN_KERNEL void through_lambda(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int m = n;
  auto shrink = [&](int k) { m = k; };
  for (int i = 0; i < m; ++i) {
    // CHECK: loop_bound_assigned.cpp:[[@LINE-1]]:19: error: the condition of loop 'i' reads 'm'
    b[i] = a[i];
    shrink(4);
  }
}
