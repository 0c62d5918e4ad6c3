// An unsigned counter counting down with `i >= 0`: always true, `--i` wraps.
// (Unsigned counters counting up are accepted, and down with `i > 0`,
// `i >= 1` or `i-- > 0`.)
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"
#include <cstddef>

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n) {
  for (std::size_t i = n - 1; i >= 0; --i)
    out[i] = a[i];
  // CHECK: unsigned_counter.cpp:[[@LINE-2]]:39: error: unsigned counter 'i' counts down
}
