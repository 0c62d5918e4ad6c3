// A periodic wrap written with % is correct but scatter form; the remark says
// how to get the gather form. The adjoint still compiles and is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 3
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void forward_difference(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[(i + 1) % n] - a[i];
  // CHECK: rem_wrap.cpp:[[@LINE-1]]:14: remark: read 'a[(i + 1) % n]' in kernel 'forward_difference' has an index that dpgen cannot invert (not affine in the loop counters, or piecewise on a condition it cannot bound): its adjoint is computed in scatter form, serially (for the gather form, write a periodic wrap as a conditional index: i == n - 1 ? 0 : i + 1)
}
