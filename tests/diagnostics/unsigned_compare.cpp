// A loop condition that C evaluates in an unsigned type, where a value below zero would be
// a huge number: the user's loop runs other iterations than dpgen's, which counts with the
// values as numbers. Refused unless the lowest value compared is provably >= 0 (found by a
// review of while loops: each of these was accepted with a silently wrong adjoint).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cstddef>

// A signed start converted: with start < 0 the loop runs no iteration in C.
DPGEN_KERNEL void signed_start(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n,
                               int start) {
  for (int i = start; i < n; ++i)
    // CHECK-DAG: unsigned_compare.cpp:[[@LINE-1]]:25: error: the condition of loop 'i' compares in the unsigned type 'unsigned long'
    out[i + 2] = a[i + 2] * a[i + 2];
}

// The same as a while loop.
DPGEN_KERNEL void signed_start_while(DPGEN_IN const double* a, DPGEN_OUT double* out,
                                     std::size_t n, int start) {
  int i = start;
  while (i < n) {
    // CHECK-DAG: unsigned_compare.cpp:[[@LINE-1]]:12: error: the condition of loop 'i' compares in the unsigned type
    out[i + 2] = a[i + 2] * a[i + 2];
    ++i;
  }
}

// A signed bound of a count down converted: `lo = -1` stops the loop at once in C.
DPGEN_KERNEL void signed_bound(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n,
                               int lo) {
  for (std::size_t i = n; i-- > lo;)
    // CHECK-DAG: unsigned_compare.cpp:[[@LINE-1]]:31: error: the condition of loop 'i' compares in the unsigned type
    out[i] = a[i] * a[i];
}

// Unsigned arithmetic that wraps in the bound: `lo - 1` with lo = 0 is the largest size_t.
DPGEN_KERNEL void wrapped_bound(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n,
                                std::size_t lo) {
  std::size_t i = n;
  while (i-- > lo - 1)
    // CHECK-DAG: unsigned_compare.cpp:[[@LINE-1]]:14: error: the condition of loop 'i' compares in the unsigned type
    out[i] = a[i] * a[i];
}

// Counting down to a signed bound by --i.
DPGEN_KERNEL void signed_bound_step(DPGEN_IN const double* a, DPGEN_OUT double* out, unsigned n,
                                    int lo) {
  unsigned i = n;
  while (i > lo) {
    // CHECK-DAG: unsigned_compare.cpp:[[@LINE-1]]:12: error: the condition of loop 'i' compares in the unsigned type 'unsigned int'
    out[i - 1] = a[i - 1] * a[i - 1];
    --i;
  }
}
