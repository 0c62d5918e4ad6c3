// Loops with companion counters (`for (i = 0, j = n - 1; i < n; ++i, --j)`)
// and strided count-downs are accepted (tests/styles/multi_counters.cpp).
// What is not: a condition on both counters or on neither, a companion
// whose start reads the other counter, one that does not step once per
// iteration or is changed in the body, an unsigned companion counting down
// that may go below zero in the body, an unsigned strided count-down that
// can wrap, a companion of a strided loop whose start moves, and a C89
// companion read after its loop.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void converging(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:30: error: a loop with counters 'i', 'j' tests exactly one of them in its condition ('i < n'); the others follow it [dpgen-loop]
  for (int i = 0, j = n - 1; i < j; ++i, --j)
    b[i] = a[j];
}

DPGEN_KERNEL void start_from_other(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:23: error: the initial value of loop counter 'j' reads counter 'i' of the same loop; give each counter a value of its own [dpgen-loop]
  for (int i = 0, j = i + 1; i < n - 1; ++i, ++j)
    b[i] = a[j];
}

DPGEN_KERNEL void not_stepped(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:3: error: loop counter 'j' must have an integer type and step by a constant once per iteration in the loop's increment ('++j', '--j', 'j += 2') [dpgen-loop]
  for (int i = 0, j = 0; i < n; ++i)
    b[i] = a[j];
}

DPGEN_KERNEL void stepped_twice(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:43: error: the increment of a loop with several counters steps each of them once: '++i, --j' [dpgen-loop]
  for (int i = 0, j = 0; i < n; ++i, ++j, ++j)
    b[i] = a[j];
}

DPGEN_KERNEL void changed_in_body(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0, j = 0; i < n; ++i, ++j) {
    b[i] = a[j];
    // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:7: error: loop counter 'j' is modified in the loop body [dpgen-loop]
    j += 1;
  }
}

DPGEN_KERNEL void unsigned_companion(DPGEN_IN const double* a, DPGEN_OUT double* b, unsigned n) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:47: error: unsigned counter 'j' steps beside loop counter 'i', and dpgen cannot prove from the loop's bounds that it stays >= 0 in the body (where it would wrap around); use a signed counter [dpgen-loop]
  for (unsigned i = 0, j = n / 2; i < n; ++i, --j)
    b[i] = a[j] * (j < 3 ? 1.0 : 2.0);
}

DPGEN_KERNEL void unsigned_up_from_below(DPGEN_IN const double* a, DPGEN_OUT double* b,
                                         unsigned n, unsigned off) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:49: error: unsigned counter 'j' steps beside loop counter 'i'
  for (unsigned i = 0, j = off - 2; i < n; ++i, ++j)
    b[i] = a[i] * (j < 10 ? 1.0 : 2.0);
}

DPGEN_KERNEL void unsigned_wraps(DPGEN_IN const double* a, DPGEN_OUT double* b, unsigned n) {
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:32: error: unsigned counter 'i' counts down by 3: it wraps around at 0 unless the loop stops at or above 3 ('i >= 3'); use a signed counter [dpgen-loop]
  for (unsigned i = n; i >= 2; i -= 3)
    b[i] = a[i];
}

DPGEN_KERNEL void moving_strided(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int j = 0; j < n; ++j)
    // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:5: error: a strided loop whose start moves with the outer counters has one counter; compute 'k' from 'i' in the body [dpgen-loop]
    for (int i = j % 2, k = 0; i < n; i += 2, ++k)
      b[j * n + i] = a[k];
}

DPGEN_KERNEL void read_after(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int i, j;
  for (i = 0, j = 1; i < n; ++i, ++j)
    b[i] = a[j];
  // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:12: error: loop counter 'j' is read after its loop; use the loop bound instead
  b[0] = a[j];
}

DPGEN_KERNEL void before_and_in_body(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int p = 0;
  for (int i = 0; i < n; ++i, ++p) {
    b[i] = a[p];
    // CHECK-DAG: multi_counters.cpp:[[@LINE+1]]:6: error: loop counter 'p' is modified in the loop body [dpgen-loop]
    p++;
  }
}
