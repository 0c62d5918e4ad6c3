// The size of a DPGEN_OUT std::vector is not the kernel's to read: the adjoint receives only
// the output's seed, and with the seed's size standing in for the output's a seed of another
// length would silently give the gradient of another kernel (a sum over fewer elements).
// Sizes come from inputs (u.size()) or parameters (accepted: tests/styles/vector_sums.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cstddef>
#include <vector>

DPGEN_KERNEL void normalise_to_output(DPGEN_IN const std::vector<double>& a,
                                      DPGEN_OUT std::vector<double>& w) {
  // CHECK-DAG: vector_sizes.cpp:[[@LINE+1]]:25: error: the size of output 'w' is outside the kernel subset: its adjoint receives only the seed 'w_adj', whose size it cannot check against 'w'; take the size from an input (u.size()) or a parameter
  const std::size_t m = w.size();
  double s = 0.0;
  for (std::size_t i = 0; i < m; ++i)
    s += a[i] * a[i];
  for (std::size_t i = 0; i < m; ++i)
    w[i] = a[i] / (1.0 + s);
}

DPGEN_KERNEL void scale_by_output_size(DPGEN_IN const std::vector<double>& a,
                                       DPGEN_OUT std::vector<double>& w) {
  // CHECK-DAG: vector_sizes.cpp:[[@LINE+1]]:31: error: the size of output 'w' is outside the kernel subset
  for (std::size_t i = 0; i < w.size(); ++i)
    w[i] = a[i] * static_cast<double>(a.size());
}
