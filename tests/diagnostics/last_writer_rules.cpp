// Later-writer-wins and one-iteration stores (tests/styles/last_writer.cpp)
// that stay errors: the overwriting store is conditional (which instance is
// last depends on the data), the two stores meet across rows of a 2D loop
// (a shift over two counters), and a store in the else arm of `i == 0`
// (every other iteration writes the element).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void conditional_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    if (a[j] > 0)
      K[j] = a[j];
    K[j + 1] = 0.5 * a[j];
    // CHECK: last_writer_rules.cpp:[[@LINE-1]]:5: error: output 'K' is written at 'K[j + 1]' here and at 'K[j]' on line {{[0-9]+}} of the same loop
  }
}

DPGEN_KERNEL void across_rows(DPGEN_IN const double* a, DPGEN_OUT double* K, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      K[j * nx + i] = a[j * nx + i];
      K[j * nx + i + 1] = 0.5 * a[j * nx + i];
      // CHECK: last_writer_rules.cpp:[[@LINE-1]]:7: error: output 'K' is written at 'K[j * nx + i + 1]' here and at 'K[j * nx + i]' on line {{[0-9]+}} of the same loop
    }
}

DPGEN_KERNEL void else_arm(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0)
      out[1] = a[i];
    else
      out[0] = a[i];
    // CHECK: last_writer_rules.cpp:[[@LINE-1]]:7: error: output 'out' is written at the same index by every iteration of loop 'i'
  }
}
