// An unsigned loop counter (adjoint loops shift indices below zero).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"
#include <cstddef>

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    out[i] = a[i];
  // CHECK: unsigned_counter.cpp:[[@LINE-2]]:20: error: loop counter 'i' must have a signed integer type
}
