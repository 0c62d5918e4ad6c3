// Loop nests under conditions that can both hold still write the same
// elements (issue 20, defect 4: only arms that exclude each other are
// exempt): two ifs on different flags, two ifs on the same test, and a
// condition on a counter, which is not one value for the whole call.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void two_flags(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int f, int g) {
  if (f == 1)
    for (int i = 0; i < n; ++i)
      out[i] = a[i];
  if (g == 1)
    for (int i = 0; i < n; ++i)
      out[i] = 2.0 * a[i];
  // CHECK: branches_not_exclusive.cpp:[[@LINE-1]]:7: error: output 'out' is also written on line 13 in another loop nest
}

DPGEN_KERNEL void same_test(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int f) {
  if (f == 1)
    for (int i = 0; i < n; ++i)
      out[i] = a[i];
  if (f == 1)
    for (int i = 0; i < n; ++i)
      out[i] = 2.0 * a[i];
  // CHECK: branches_not_exclusive.cpp:[[@LINE-1]]:7: error: output 'out' is also written on line 23 in another loop nest
}

DPGEN_KERNEL void counter_test(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < 2; ++j) {
    if (j == 0)
      for (int i = 0; i < n; ++i)
        out[i] = a[i];
    else
      for (int i = 0; i < n; ++i)
        out[i] = 2.0 * a[i];
    // CHECK: branches_not_exclusive.cpp:[[@LINE-1]]:9: error: output 'out'
  }
}
