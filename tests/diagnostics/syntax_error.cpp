// A syntax error is reported by Clang, and nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i]
  // CHECK: syntax_error.cpp:[[@LINE-1]]:18: error: expected ';' after expression
}
// CHECK: dpgen: errors found; no file written
