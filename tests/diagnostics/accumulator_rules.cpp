// A local summed in a loop is an accumulator only where the loop adds to it
// and nothing else reads it there (issue 20): a prefix sum reads it inside
// the loop, a product or a decaying recurrence is no sum. Those stay errors,
// each in one run.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void prefix_sum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    s += a[i];
    out[i] = s;
    // CHECK: accumulator_rules.cpp:[[@LINE-1]]:14: error: 's' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration
  }
}

DPGEN_KERNEL void product(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double p = 1;
  for (int i = 0; i < n; ++i)
    p *= a[i];
  // CHECK: accumulator_rules.cpp:[[@LINE-1]]:5: error: 'p' is declared outside the loop and assigned inside it
  out[0] = p;
}

DPGEN_KERNEL void decay(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i)
    s = 0.5 * s + a[i];
  // CHECK: accumulator_rules.cpp:[[@LINE-1]]:15: error: 's' is declared outside the loop and assigned inside it
  out[0] = s;
}

// The same rules through lambdas and helpers (tests/styles/lambda_accumulators.cpp: the sums
// they may add): a running sum a lambda adds to and the loop reads, a helper's recurrence
// through `double&`, and a C helper that reads the sum it adds to through `double*`; the
// message names the caller's variable where the callee uses it.
DPGEN_KERNEL void lambda_prefix(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  auto add = [&](double x) { s += x * x; };
  for (int i = 0; i < n; ++i) {
    add(a[i]);
    out[i] = s;
    // CHECK: accumulator_rules.cpp:[[@LINE-1]]:14: error: 's' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration
  }
}

static void halve_add(double& acc, double x) { acc = 0.5 * acc + x; }
// CHECK: accumulator_rules.cpp:[[@LINE-1]]:60: error: 's' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration

DPGEN_KERNEL void helper_recurrence(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    halve_add(s, a[i]);
  out[0] = s;
  // CHECK: accumulator_rules.cpp:[[@LINE-1]]:12: error: 's' is read after the loop that assigns it
}

static void add_and_copy(double* acc, double x, double* seen) {
  *acc += x;
  // CHECK: accumulator_rules.cpp:[[@LINE-1]]:3: error: 's' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration
  *seen = *acc;
}

DPGEN_KERNEL void pointer_read(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0, t = 0.0;
  for (int i = 0; i < n; ++i)
    add_and_copy(&s, a[i], &t);
  out[0] = s + t;
  // CHECK: accumulator_rules.cpp:[[@LINE-1]]:12: error: 's' is read after the loop that assigns it
}

// A sum added to at two loop depths: dpgen would add all of one nest's terms before the
// other's, which rounds otherwise than the kernel's order (with b = {1e16, -1e16} and a = 1
// the kernel's total is 3, the reordered one 6); a sum of the inner loop of its own is fine.
DPGEN_KERNEL void two_depths(DPGEN_IN const double* a, DPGEN_IN const double* b,
                             DPGEN_OUT double* out, int nx, int ny) {
  double s = 0.0;
  for (int j = 0; j < ny; ++j) {
    s = s + b[j];
    for (int i = 0; i < nx; ++i)
      s += a[j * nx + i];
    // CHECK: accumulator_rules.cpp:[[@LINE-1]]:7: error: 's' is added to here and on line [[@LINE-3]], in loops nested otherwise
  }
  out[0] = s * s;
}

DPGEN_KERNEL void two_depths_split(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                   DPGEN_OUT double* out, int nx, int ny) {
  double s = 0.0;
  for (int j = 0; j < ny; ++j) {
    double t = 0.0;
    for (int i = 0; i < nx; ++i)
      t += a[j * nx + i];
    s += b[j] + t;
  }
  out[0] = s * s;
}
