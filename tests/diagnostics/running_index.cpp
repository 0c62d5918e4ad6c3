// Running indices (`b[idx] = ...; idx++;`) are accepted where each
// iteration's value has a closed form (tests/styles/running_index.cpp). What
// is not: a step under a condition or after a `continue`, two inner loops
// that both step it, a read beside an inner loop that steps it, a step that
// changes from one iteration to the next, a read after the loop where dpgen
// cannot prove the loop runs, and a step inside an expression that also reads
// the index (`b[idx++] = a[idx]`, or through a lambda: which value it reads is
// the order of evaluation's) or that runs only in an arm of `?:` (`b[idx++] =
// x` alone is accepted).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void step_in_if(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  for (int i = 0; i < n; ++i) {
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:14: error: 'idx' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration: {{.*}}; a running index is in the subset too: stepped (`k++`, `k += s`) by the same amount in every iteration, outside any `if`, in a loop with no `continue`, `break` or `return`, and read inside the innermost loop that steps it [dpgen-unsupported]
    b[i] = a[idx];
    if (a[i] > 0.0)
      idx++;
  }
}

DPGEN_KERNEL void continue_first(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  for (int i = 0; i < n; ++i) {
    if (i == 2)
      continue;
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:7: error: 'idx' is declared outside the loop and assigned inside it
    b[idx] = a[i];
    idx++;
  }
}

DPGEN_KERNEL void two_inner(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, int m) {
  int idx = 0;
  for (int j = 0; j < n; ++j) {
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:37: error: 'idx' is declared outside the loop and assigned inside it
    for (int i = 0; i < m; ++i) { b[idx] = a[idx]; idx++; }
    for (int i = 0; i < m; ++i) { b[idx] = 2.0 * a[idx]; idx++; }
  }
}

DPGEN_KERNEL void read_beside(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, int m) {
  int idx = 0;
  for (int j = 0; j < n; ++j) {
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:7: error: 'idx' is declared outside the loop and assigned inside it
    b[idx] = a[idx];
    idx++;
    for (int i = 0; i < m; ++i) { b[idx] = 2.0 * a[idx]; idx++; }
  }
}

DPGEN_KERNEL void step_by_counter(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  // CHECK-DAG: running_index.cpp:[[@LINE+1]]:3: error: 'idx' is stepped in this loop by an amount that changes from one iteration to the next (or is not an integer sum of sizes): a running index must step by the same amount in every iteration; compute it from the counters instead [dpgen-loop]
  for (int i = 0; i < n; ++i) {
    b[idx] = a[idx];
    idx += i;
  }
}

DPGEN_KERNEL void read_after(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  for (int i = 0; i < n; ++i) {
    b[idx] = a[idx];
    idx++;
  }
  // CHECK-DAG: running_index.cpp:[[@LINE+1]]:5: error: 'idx' is read after the loops that step it, and dpgen cannot prove that each of them runs (its upper bound at least its lower one) to count its steps; compute it from the loops' bounds [dpgen-unsupported]
  b[idx] = a[idx] * a[idx];
}

DPGEN_KERNEL void step_and_read(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:10: error: increment/decrement inside an expression is outside the kernel subset [dpgen-unsupported]
    b[idx++] = a[idx] * a[i];
}

DPGEN_KERNEL void step_in_an_arm(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:30: error: increment/decrement inside an expression is outside the kernel subset [dpgen-unsupported]
    b[i] = a[i] > 0.0 ? a[idx++] : 0.0;
}

DPGEN_KERNEL void step_beside_a_lambda(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  auto get = [&]() { return a[idx]; };
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: running_index.cpp:[[@LINE+1]]:10: error: increment/decrement inside an expression is outside the kernel subset [dpgen-unsupported]
    b[idx++] = get() * a[i];
}

// (the review's case: the outer loop provably runs, the inner one may not,
// and a read after the nest would count nx - 2 < 0 steps per row)
DPGEN_KERNEL void read_after_nest(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  if (ny < 1)
    return;
  int idx = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 1; i < nx - 1; ++i) {
      b[idx] = a[idx] * a[idx];
      idx++;
    }
    idx += 2;
  }
  // CHECK-DAG: running_index.cpp:[[@LINE+1]]:5: error: 'idx' is read after the loops that step it
  b[idx] = a[idx] * a[0];
}
