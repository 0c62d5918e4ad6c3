// Void helpers with out-parameters (`double& r`, `double* r` called with
// `&x`) are inlined; what would need more than copy-in/copy-out is rejected.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

static void early(double a, double& r) {
  r = a;
  if (a > 0.0)
    return;
  // CHECK: helper_outparams.cpp:[[@LINE-1]]:5: error: 'return' inside a branch of void helper 'early': assign the out-parameters in if/else instead
  r = -a;
}
DPGEN_KERNEL void k_early(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    double r;
    early(a[i], r);
    o[i] = r;
  }
}

static void two(double a, double& x, double& y) { x = a, y = 2 * a; }
DPGEN_KERNEL void k_alias(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    double r = 0;
    two(a[i], r, r);
    // CHECK: helper_outparams.cpp:[[@LINE-1]]:18: error: local 'r' is passed to two out-parameters of helper 'two'
    o[i] = r;
  }
}

static double both(double a, double* extra) {
  *extra = a;
  return a * a;
}
// CHECK: helper_outparams.cpp:[[@LINE-4]]:38: error: helper 'both' returns a value and has out-parameter 'extra'
DPGEN_KERNEL void k_both(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    double e;
    o[i] = both(a[i], &e);
  }
}
