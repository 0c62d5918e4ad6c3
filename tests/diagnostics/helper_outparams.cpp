// Void helpers with out-parameters (`double& r`, `double* r` called with
// `&x`) are inlined; what would need more than copy-in/copy-out is rejected.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

// A return inside a small constant loop that dpgen unrolls: the copies after
// it would not see that it escaped (they stored and read as if it had not).
static void scaled_sum(double x, double& r) {
  const double w[3] = {0.5, -1.0, 2.0};
  r = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (x * w[k] < 0.0)
      return;
    // CHECK: helper_outparams.cpp:[[@LINE-1]]:7: error: 'return' in a small constant loop that dpgen unrolls
    r += x * w[k];
  }
}
DPGEN_KERNEL void k_unrolled_return(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    double r;
    scaled_sum(a[i], r);
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
