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

// A call in an operand that C++ evaluates only under a condition (a `?:`
// arm, the right side of `&&`) is lowered as if it always ran, so it must not
// assign the caller's variables or store (a wrong value and gradient until
// 2026-11-30). (A lambda that returns inside a branch and assigns its
// caller's variables is merged per way out: tests/styles/early_returns.cpp.)
DPGEN_KERNEL void sets_in_conditional(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double d = 1.0;
    auto sq = [&](double x) {
      d = 2.0 * x;
      // CHECK: lambda_rules.cpp:[[@LINE-1]]:7: error: 'd' is assigned by a call in an operand that C++ evaluates only under a condition (line [[#@LINE+3]]: a '?:' arm
      return x * x;
    };
    const double v = a[i] < 0.0 ? 0.0 : sq(a[i]);
    out[i] = v + d * a[i];
  }
}

DPGEN_KERNEL void sets_in_and(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double d = 1.0;
    auto big = [&](double x) {
      d = 2.0 * x;
      // CHECK: lambda_rules.cpp:[[@LINE-1]]:7: error: 'd' is assigned by a call in an operand that C++ evaluates only under a condition (line [[#@LINE+4]]: a '?:' arm, or the right side of '&&' / '||')
      return x > 0.5;
    };
    double v = 0.0;
    if (a[i] > 0.0 && big(a[i]))
      v = a[i];
    out[i] = v + d * a[i];
  }
}

DPGEN_KERNEL void stores_in_conditional(DPGEN_INOUT double* u, DPGEN_IN const double* a,
                                        DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    auto bump = [&](double x) {
      u[i] += x;
      // CHECK: lambda_rules.cpp:[[@LINE-1]]:7: error: a call in an operand that C++ evaluates only under a condition (line [[#@LINE+3]]: a '?:' arm, or the right side of '&&' / '||') stores into 'u'
      return x;
    };
    out[i] = a[i] < 0.0 ? 0.0 : bump(a[i]);
  }
}

// A helper's out-parameter (or `const&` parameter) and a lambda it runs that
// captured the same local by reference: the parameter is inlined as a copy
// (copied back), so the two would not see each other's changes.
template <class Fn> void run_then_add(double& r, const Fn& f, double x) {
  f(x);
  r = r + 1.0;
}

DPGEN_KERNEL void out_param_alias(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double d = 1.0;
    auto set = [&](double y) { d = y; };
    run_then_add(d, set, a[i]);
    // CHECK: lambda_rules.cpp:[[@LINE-1]]:5: error: 'd' is passed to parameter 'r' of helper 'run_then_add' (inlined as a copy) and captured by reference by a lambda passed to the same call
    out[i] = d;
  }
}
// An argument that assigns the out-parameter's local before the helper runs
// (C++ evaluates it first; the copy bound to the parameter would be stale).
static void add_to(double& r, double x) { r = r + x; }

DPGEN_KERNEL void out_param_argument(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double d = 1.0;
    auto set = [&](double y) {
      d = y;
      return y;
    };
    add_to(d, set(a[i]));
    // CHECK: lambda_rules.cpp:[[@LINE-1]]:5: error: 'd' is passed to out-parameter 'r' of helper 'add_to' and also assigned during the call (by a lambda that captured it by reference, or in another argument)
    out[i] = d;
  }
}
// The called lambda itself captures the local it is passed by reference
// (a stale read of `r` through the capture: a wrong value and gradient until
// 2026-11-30).
DPGEN_KERNEL void self_alias(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double r = 0.0, s = 0.0;
    auto g = [&](double* f, double x) {
      *f = x * x;
      s = r + x;
    };
    g(&r, a[i]);
    // CHECK: lambda_rules.cpp:[[@LINE-1]]:5: error: 'r' is passed to parameter 'f' of this lambda (inlined as a copy) and captured by reference by the lambda itself
    out[i] = s + r;
  }
}

DPGEN_KERNEL void self_alias_cref(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double r = a[i], s = 0.0;
    auto g = [&](const double& f, double x) {
      r = x * x;
      s = f + x;
    };
    g(r, a[i]);
    // CHECK: lambda_rules.cpp:[[@LINE-1]]:5: error: 'r' is passed to parameter 'f' of this lambda (inlined as a copy) and captured by reference by the lambda itself
    out[i] = s + r;
  }
}
// CHECK-NOT: a lambda is called through
