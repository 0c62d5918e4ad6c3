// Member kernels (tests/styles/member_*.cpp) are methods of a class; the
// forms outside the subset are errors that say so, and nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

template <typename T> struct Solver {
  const T* a DPGEN_IN;
  T* out DPGEN_OUT;
  DPGEN_KERNEL void k(int n) const {
    // CHECK: member_kernel.cpp:[[@LINE-1]]:21: error: a member kernel of a class template is outside the kernel subset
    for (int i = 0; i < n; ++i)
      out[i] = a[i];
  }
};
template struct Solver<double>;

struct ConstOut {
  const double* a DPGEN_IN;
  const double* out DPGEN_OUT;
  // CHECK: member_kernel.cpp:[[@LINE-1]]:17: error: DPGEN_OUT parameter 'out' points to const
  DPGEN_KERNEL void k(int n) const {
    for (int i = 0; i < n; ++i)
      a[i] + 1.0;
  }
};

struct Race {
  const double* a DPGEN_IN;
  double* sum DPGEN_OUT;
  DPGEN_KERNEL void total(int n) const;
};

template <typename F> void for_each_cell(int n, const F& f) {
  for (int i = 0; i < n; ++i)
    f(i);
}

void Race::total(int n) const {
  for_each_cell(n, [&](int i) { sum[0] += a[i]; });
  // CHECK: member_kernel.cpp:[[@LINE-1]]:33: error: '+=' into 'sum' in the body of a parallel-for ('for_each_cell'), at an element its iterations over 'i' share
}
