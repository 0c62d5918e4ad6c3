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
    out[i] = std::tgamma(a[i]);
  // CHECK: unknown_call.cpp:[[@LINE-1]]:14: error: call to 'tgamma', which dpgen cannot differentiate; the kernel subset calls only std::min, std::max, std::fmin, std::fmax, std::abs/fabs, std::sqrt, std::exp, std::log, std::sin, std::cos, std::tanh, std::pow, std::floor, std::ceil, std::atan2, std::hypot, std::erf, std::cbrt, std::copysign, std::fma, std::log1p, std::expm1, std::clamp [dpgen-call]{{$}}
}

DPGEN_KERNEL void k2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = helper(a[i]);
  // CHECK: unknown_call.cpp:[[@LINE-1]]:14: error: call to 'helper', whose body dpgen cannot see: helper functions are inlined, so define 'helper' in the kernel's file or a header it includes
}

// std::hypot has a three-argument overload (C++17); the table's row has two.
DPGEN_KERNEL void k3(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = std::hypot(a[i], 1.0, 2.0);
  // CHECK: unknown_call.cpp:[[@LINE-1]]:14: error: 'hypot' takes 2 argument(s) in the kernel subset
}
