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

// A helper's own loop is run as a parallel-for (each iteration on its own): what it assigns
// through an out-parameter there carries no value across its iterations. Until 2026-12-01
// these were accepted and the loop's assignments through `*p` were dropped (the caller's
// local kept its value from before the call: a wrong value and gradient).
static void add_row(double* acc, const double* a, int j, int m) {
  for (int i = 0; i < m; ++i)
    *acc += a[j * m + i] * a[j * m + i];
  // CHECK: helper_outparams.cpp:[[@LINE-1]]:10: error: 'acc' is updated in the loop of helper 'add_row', which dpgen runs as a parallel loop
}
DPGEN_KERNEL void k_row_total(DPGEN_IN const double* a, DPGEN_OUT double* o, int nx, int ny) {
  double s = 0.0;
  for (int j = 0; j < ny; ++j)
    add_row(&s, a, j, nx);
  o[0] = s;
}

static void add_row_once(double* acc, const double* a, int m) {
  for (int i = 0; i < m; ++i)
    *acc += a[i] * a[i];
  // CHECK: helper_outparams.cpp:[[@LINE-1]]:5: error: 'acc' is assigned in the loop of helper 'add_row_once', which dpgen runs as a parallel loop
}
DPGEN_KERNEL void k_once(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double r = 0.0;
  add_row_once(&r, a, n);
  o[0] = r;
}

static void last_square(double* out, const double* a, int m) {
  for (int i = 0; i < m; ++i)
    *out = a[i] * a[i];
}
DPGEN_KERNEL void k_last(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double s = 5.0;
  last_square(&s, a, n);
  o[0] = s;
  // CHECK: helper_outparams.cpp:[[@LINE-1]]:10: error: 'out' is read after the loop that assigns it
}

static void grow(double* v, int m) {
  for (int i = 0; i < m; ++i)
    *v *= 1.5;
  // CHECK: helper_outparams.cpp:[[@LINE-1]]:5: error: 'v' is assigned in the loop of helper 'grow', which dpgen runs as a parallel loop
}
DPGEN_KERNEL void k_grow(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double s = a[0];
  grow(&s, n);
  o[0] = s;
}
