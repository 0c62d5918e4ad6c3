// An output that is not floating point.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT int* out, int n) {
  // CHECK: int_output.cpp:[[@LINE-1]]:62: error: DPGEN_OUT parameter 'out' must point to float or double, not 'int'
  for (int i = 0; i < n; ++i)
    out[i] = a[i] > 0.0;
}
