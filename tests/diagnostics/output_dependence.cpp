// A loop-carried dependence through the output (a running sum written in
// place): each element depends on the previous one's output.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void cumsum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  out[0] = a[0];
  for (int i = 1; i < n; ++i)
    out[i] = out[i - 1] + a[i];
  // CHECK: output_dependence.cpp:[[@LINE-1]]:14: error: output 'out' is read here and written on line 11, in the same loop or later: a value carried from one iteration to the next through an output
}
