// A call to a library function dpgen has no rule for (a helper declared but
// not defined is reported too: dpgen inlines the helpers it can see).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cmath>

double helper(double x);

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = std::erf(a[i]);
  // CHECK: unknown_call.cpp:[[@LINE-1]]:14: error: call to 'erf', which dpgen cannot differentiate; the kernel subset calls only std::min
}

DPGEN_KERNEL void k2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = helper(a[i]);
  // CHECK: unknown_call.cpp:[[@LINE-1]]:14: error: call to 'helper', whose body dpgen cannot see: helper functions are inlined, so define 'helper' in the kernel's file or a header it includes
}
