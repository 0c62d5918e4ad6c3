// A range-based for over a local table is unrolled
// (tests/styles/range_for_tables.cpp). What is not accepted: one over a
// kernel array or a std::vector parameter, a non-const reference that could
// write the table, a body that assigns the table (also a std::array's element
// through operator[]), and a table element read before it is set. And a
// std::array element summed in a loop and read after it (once read as the
// value before the loop: 0).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <array>
#include <vector>

DPGEN_KERNEL void over_vector(DPGEN_IN const std::vector<double>& a, DPGEN_OUT double* b) {
  double s = 0.0;
  // CHECK-DAG: range_for.cpp:[[@LINE+1]]:3: error: a range-based for runs over a local array of constant length (a table: 'for (double w : weights)'); over anything else, use an integer counter [dpgen-loop]
  for (double x : a)
    s += x * x;
  b[0] = s;
}

DPGEN_KERNEL void writes_through(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  double w[2] = {1.0, 2.0};
  // CHECK-DAG: range_for.cpp:[[@LINE+1]]:16: error: 'x' is a non-const reference into local array 'w'; a range-based for reads its elements ('const double& x' or 'double x'): assign them through an integer counter [dpgen-loop]
  for (double& x : w)
    x *= 2.0;
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * w[0];
}

DPGEN_KERNEL void assigns_table(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  double w[2] = {1.0, 2.0};
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    // CHECK-DAG: range_for.cpp:[[@LINE+1]]:5: error: the body of a range-based for over 'w' assigns 'w'; fill the array in a loop of its own [dpgen-loop]
    for (double x : w) {
      s += x * a[i];
      w[0] = s;
    }
    b[i] = s;
  }
}

DPGEN_KERNEL void unset_element(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double d[2];
    d[0] = a[i];
    double s = 0.0;
    // CHECK-DAG: range_for.cpp:[[@LINE+1]]:21: error: element 1 of local array 'd' is read before it is assigned [dpgen-loop]
    for (double x : d)
      s += x;
    b[i] = s;
  }
}

DPGEN_KERNEL void writes_std_array(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 3> t{a[i], 1.0, 2.0};
    double s = 0.0;
    // CHECK-DAG: range_for.cpp:[[@LINE+1]]:5: error: the body of a range-based for over 't' assigns 't'; fill the array in a loop of its own [dpgen-loop]
    for (const double& w : t) {
      t[1] = 2.0 * w;
      s += w;
    }
    b[i] = s;
  }
}

DPGEN_KERNEL void std_array_sum_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  std::array<double, 1> acc{};
  for (int i = 0; i < n; ++i)
    acc[0] += a[i] * a[i];
  // CHECK-DAG: range_for.cpp:[[@LINE+1]]:10: error: 'acc' is read after the loop that assigns it
  b[0] = acc[0];
}
