// While loops: one that counts (its counter stepped by the body's last statement, or counted
// down by the condition) is read as its for loop (tests/styles/while_loops.cpp); every other
// one is refused at the loop, with the for loop's rules where it is read as one.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s --implicit-check-not="must be a local variable"
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cstddef>

// The trip count depends on the data: not a bound.
DPGEN_KERNEL void data_bound(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (a[i] > 0.0 && i < n) {
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:10: error: loop condition must compare the counter 'i' with a bound
    out[i] = a[i];
    ++i;
  }
}

// A `continue` would skip the step at the end of the body, which a for loop runs.
DPGEN_KERNEL void skips_step(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (i < n) {
    if (a[i] < 0.0)
      continue;
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:7: error: 'continue' in a while loop skips the step of its counter 'i'
    out[i] = a[i];
    ++i;
  }
}

// The step inside a branch, not the body's last statement: no counter.
DPGEN_KERNEL void step_in_branch(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (i < n) {
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:3: error: a while loop is in the kernel subset as the for loop it is
    out[i] = a[i];
    if (n > 2) {
      ++i;
    }
  }
}

// The counter also stepped in the middle of the body: the for loop's rule.
DPGEN_KERNEL void stepped_twice(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (i < n) {
    out[i] = a[i];
    i += 1;
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:7: error: loop counter 'i' is modified in the loop body
    ++i;
  }
}

// The counter read after its loop (C leaves it at n): the for loop's rule.
DPGEN_KERNEL void read_after(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (i < n - 1) {
    out[i] = a[i] * a[i];
    i++;
  }
  out[i] = a[i];
  // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:7: error: loop counter 'i' is read after its loop
}

// A counter without a value when the loop starts.
DPGEN_KERNEL void no_start(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i;
  while (i < n) {
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:3: error: 'i' may be used before it has a value
    out[i] = a[i];
    ++i;
  }
}

// do/while runs its body before the first test: refused.
DPGEN_KERNEL void do_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  do {
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:3: error: do/while loops are outside the kernel subset
    out[i] = a[i];
    ++i;
  } while (i < n);
}

// The counter stepped first, then read: the for loop steps after the body.
DPGEN_KERNEL void step_first(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = -1;
  while (i < n - 1) {
    ++i;
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:5: error: a while loop is in the kernel subset as the for loop it is{{.*}}this statement steps the counter 'i' before the end of the body
    out[i] = a[i];
  }
}

// A parameter counted down: the loop would change the kernel's argument.
DPGEN_KERNEL void parameter_counter(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  while (n-- > 0)
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:3: error: the counter 'n' of this while loop is a parameter of the kernel
    out[n] = 2.0 * a[n];
}

// An early return: it leaves the kernel, not the iteration.
DPGEN_KERNEL void early_return(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (i < n) {
    if (a[0] < 0.0)
      return;
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:7: error: 'return' inside a loop is outside the kernel subset (it would leave every loop and the kernel); to skip the rest of an iteration, use an if/else
    out[i] = a[i];
    ++i;
  }
}

// An unsigned count down whose test never fails.
DPGEN_KERNEL void unsigned_ge_zero(DPGEN_IN const double* u, DPGEN_OUT double* v, std::size_t n) {
  std::size_t k = n;
  while (k-- >= 0)
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:14: error: 'k-- >= 0' is always true in the unsigned type '{{[a-z ]+}}': the loop never ends; count down with 'k-- > 0', which runs the body down to k = 0
    v[k] = u[k];
}

// An unsigned counter stepped down before its test: at 0 it wraps.
DPGEN_KERNEL void unsigned_pre_decrement(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                         std::size_t n) {
  std::size_t k = n;
  while (--k > 0)
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:10: error: the unsigned counter 'k' is stepped down before it is tested ('--k'): at 0 it wraps around instead of ending the loop; test it before the step ('k-- > lo' runs the body down to k = lo), or make it signed
    v[k] = u[k];
}

// A counter whose declaration is refused: its loop says nothing more (no "must be a local
// variable": the implicit check of the RUN line).
DPGEN_KERNEL void refused_counter(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  unsigned i = n - 2;
  // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:16: error: 'n - 2', converted to unsigned 'unsigned int', may go below zero here
  while (i-- > 0)
    v[i] = u[i];
}

// A signed counter stepped before a test made in an unsigned type: at -1 it compares as a
// huge number and the loop goes on.
DPGEN_KERNEL void pre_decrement_unsigned_test(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                              int n) {
  int i = n;
  while (--i >= 0u)
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:14: error: the condition of loop 'i' compares in the unsigned type 'unsigned int', where a value below zero is a huge number{{.*}}(the lowest is '-1')
    v[i] = u[i];
}

// The same conditions in a for header: an unsigned counter stepped before its test.
DPGEN_KERNEL void for_pre_decrement(DPGEN_IN const double* u, DPGEN_OUT double* v, std::size_t n) {
  for (std::size_t k = n; --k > 0;)
    // CHECK-DAG: while_loop.cpp:[[@LINE-1]]:27: error: the unsigned counter 'k' is stepped down before it is tested ('--k')
    v[k] = u[k];
}
