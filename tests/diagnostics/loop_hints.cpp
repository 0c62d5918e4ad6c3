// Loop headers outside the subset whose messages say what to write instead.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cstddef>

// An unsigned count down that ends by wrapping around.
DPGEN_KERNEL void wrap_down(DPGEN_IN const double* u, DPGEN_OUT double* v, std::size_t n) {
  for (std::size_t i = n - 1; i < n; --i)
    // CHECK-DAG: loop_hints.cpp:[[@LINE-1]]:38: error: loop direction does not match its condition: an unsigned counter counting down to 0 under `i < n` ends by wrapping around, which dpgen does not follow; count down with `for (size_t i = n; i-- > 0;)`
    v[i] = u[i] * u[i];
}

// A second variable declared in the for statement, without a value.
DPGEN_KERNEL void extra_declared(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int j = 0, i; j < n; ++j) {
    // CHECK-DAG: loop_hints.cpp:[[@LINE-1]]:3: error: loop counter 'i' needs an initial value (declare other variables before the loop)
    i = j;
    v[i] = u[j];
  }
}

// A negative constant step.
#define STEP (-1)
DPGEN_KERNEL void negative_step(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; i += STEP)
    // CHECK-DAG: loop_hints.cpp:[[@LINE-1]]:26: error: loop increment must be ++i, i++, i += s or i = i + s for a constant s > 0
    v[i] = u[i];
}

// An unsigned running index stepped down.
DPGEN_KERNEL void unsigned_down(DPGEN_IN const double* u, DPGEN_OUT double* v, std::size_t n) {
  std::size_t j = n;
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = u[j - 1] * u[i];
    // CHECK-DAG: loop_hints.cpp:[[@LINE-1]]:14: error: 'j' is declared outside the loop and assigned inside it{{.*}}and, being unsigned, only stepping up (down it may wrap below zero: make it signed)
    --j;
  }
}
