// Component planes of one flat array (tests/styles/component_planes.cpp) that
// stay errors: planes that overlap for every size (the counters reach past
// the plane offset: row n of plane 0 is row 0 of plane 1), and a later loop
// that reads a plane no store writes.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void planes_overlap(DPGEN_IN const double* a, DPGEN_OUT double* f, int n, int m) {
  for (int j = 0; j < n + 1; ++j)
    for (int i = 0; i < m; ++i) {
      f[0 * n * m + j * m + i] = a[j * m + i];
      f[1 * n * m + j * m + i] = 2.0 * a[j * m + i];
      // CHECK: component_planes.cpp:[[@LINE-1]]:7: error: output 'f' is written at 'f[n * m + j * m + i]' here and at 'f[0 * n * m + j * m + i]' on line {{[0-9]+}} of the same loop: dpgen cannot prove two iterations never write the same element {{.*}} [dpgen-write-once]
    }
}

DPGEN_KERNEL void plane_unwritten(DPGEN_IN const double* a, DPGEN_OUT double* f,
                                  DPGEN_OUT double* g, int n) {
  for (int i = 0; i < n; ++i) {
    f[0 * n + i] = a[i];
    f[1 * n + i] = a[i] * a[i];
  }
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i)
      g[c * n + i] = 2.0 * f[c * n + i];
  // CHECK: component_planes.cpp:[[@LINE-1]]:28: error: reads work array 'f' at elements no earlier loop writes {{.*}} [dpgen-work-array]
}
