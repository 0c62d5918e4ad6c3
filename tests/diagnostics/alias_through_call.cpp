// An output handed to a helper together with an input: the helper could
// alias and write them; dpgen does not look into calls it has no rule for.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

void smooth(const double* in, double* out, int n);

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  smooth(a, out, n);
  // CHECK: alias_through_call.cpp:[[@LINE-1]]:3: error: call to 'smooth', whose body dpgen cannot see
}
