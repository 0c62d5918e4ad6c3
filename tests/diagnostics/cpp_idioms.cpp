// The limits of the everyday C++ idioms dpgen accepts (tests/styles/cpp_idioms.cpp,
// spelled_sums.cpp): `!=` ends only a loop stepping by one (a stride could step over the
// bound), sizeof only of what has a size before the kernel runs, a sum spelled out only
// where no term reads the sum, std::swap only of two scalar locals (and as a recurrence
// where it carries values between iterations), std::min and std::max without a comparator,
// and structured bindings and members of returned pairs are named as written. Each in one
// run.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <functional>
#include <utility>

DPGEN_KERNEL void strided_ne(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i != n; i += 2)
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:21: error: loop condition must be <, <=, > or >= ('!=' where the counter steps by one)
    out[i] = a[i];
}

DPGEN_KERNEL void vla_sizeof(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double tmp[n];
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:21: error: expression 'sizeof(tmp)' (UnaryExprOrTypeTraitExpr) is outside the kernel subset
    out[i] = a[i] * sizeof(tmp);
  }
}

DPGEN_KERNEL void sum_reads_itself(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    s = s + a[i] + 0.5 * s;
  // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:9: error: 's' is declared outside the loop and assigned inside it
  out[0] = s;
}

// `a - s` is no sum of s (s changes sign each time), and a cast to a narrower type than the
// sum's rounds the sum at each step: both recurrences. (`e + s - f` and a cast to the sum's
// own type are sums: tests/styles/spelled_sums.cpp, mid_chain_sums.)
DPGEN_KERNEL void sum_subtracted(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    s = a[i] - s;
  // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:16: error: 's' is declared outside the loop and assigned inside it
  out[0] = s;
}

DPGEN_KERNEL void sum_cast_narrower(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    s = (float)(s + a[i]);
  // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:17: error: 's' is declared outside the loop and assigned inside it
  out[0] = s;
}

// std::max, std::min and std::clamp with a comparator (a function object, a lambda or a
// function): refused at the comparator, not at the list.
static bool abs_less(double x, double y) { return x * x < y * y; }

DPGEN_KERNEL void max_comparator(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:41: error: 'std::max' with a comparator is outside the kernel subset: dpgen differentiates std::max by the order of its values
    out[i] = std::max({a[i], 0.0, 1.0}, std::greater<>());
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:34: error: 'std::min' with a comparator
    out[i] = std::min(a[i], 0.5, [](double x, double y) { return x * x < y * y; });
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:41: error: 'std::max' with a comparator
    out[i] = std::max(a[i], 0.5 * a[i], abs_less);
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:42: error: 'std::clamp' with a comparator
    out[i] = std::clamp(a[i], -0.5, 0.5, std::greater<>());
}

static std::pair<double, double> split(double x) { return {x * x, 2.0 * x}; }

DPGEN_KERNEL void bound_pair(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    auto [p, q] = split(a[i]);
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:10: error: a structured binding (auto [x, y] = ...) of type 'std::pair<double, double>' is outside the kernel subset
    out[i] = p + q;
  }
}

DPGEN_KERNEL void pair_member(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = split(a[i]).first;
  // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:26: error: expression 'split(a[i]).first' (MemberExpr) is outside the kernel subset
}

// std::swap: of two scalar locals only, and a swap that carries values from one iteration to
// the next is a recurrence like any other.
DPGEN_KERNEL void swap_carried(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double x = 0.0, y = 1.0;
  for (int i = 0; i < n; ++i) {
    std::swap(x, y);
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE-1]]:15: error: 'x' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration
    out[i] = x * a[i];
  }
}

DPGEN_KERNEL void swap_pointers(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                DPGEN_OUT double* out, int n) {
  const double* p = a;
  const double* q = b;
  // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:13: error: std::swap of 'p': dpgen swaps two scalar locals (std::swap(a, b))
  std::swap(p, q);
  for (int i = 0; i < n; ++i)
    out[i] = p[i] - q[i];
}

DPGEN_KERNEL void swap_elements(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double w[2] = {a[i], 2.0 * a[i]};
    // CHECK-DAG: cpp_idioms.cpp:[[@LINE+1]]:15: error: std::swap of 'w[0]'
    std::swap(w[0], w[1]);
    out[i] = w[0] - w[1];
  }
}
