// Lambdas are inlined at their calls (tests/styles/lambdas.cpp). A lambda
// whose copy of a local is stale at the call, one turned into a function
// pointer, and init-captures are errors (issue 20); one handed to a helper
// is inlined there (tests/styles/lambdas.cpp: lambda_for_each).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

template <typename F> double apply(F f, double x) { return f(x); }

DPGEN_KERNEL void stale_copy(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double c) {
  double s = c;
  auto scale = [=](double x) { return s * x; };
  s = 2.0 * c;
  for (int i = 0; i < n; ++i)
    out[i] = scale(a[i]);
  // CHECK: lambda_rules.cpp:[[@LINE-1]]:14: error: lambda 'scale' captured 's' by copy, and 's' changed before this call
}

DPGEN_KERNEL void as_value(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double (*sq)(double) = [](double x) { return x * x; };
  // CHECK: lambda_rules.cpp:[[@LINE-1]]:12: error: local 'sq' of type 'double (*)(double)' is outside the kernel subset
  for (int i = 0; i < n; ++i)
    out[i] = apply(sq, a[i]);
}

DPGEN_KERNEL void init_capture(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto f = [k = 2.0](double x) { return k * x; };
  // CHECK: lambda_rules.cpp:[[@LINE-1]]:13: error: lambda 'f' captures something other than the kernel's variables
  for (int i = 0; i < n; ++i)
    out[i] = f(a[i]);
}
// CHECK-NOT: a lambda is called through
