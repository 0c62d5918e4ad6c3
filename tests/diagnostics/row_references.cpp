// Rows of a std::vector<std::vector<double>> taken by reference (accepted:
// tests/styles/nested_vectors.cpp, vv_row_refs): a row or a column named by
// data is refused (first as an index that may go below zero, which the
// unsigned index of std::vector wraps; else as data-dependent), its length is
// not known to dpgen, a row copied whole is no element store, and a sum read after its
// loop needs flat arrays. Each in one run.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <vector>

using Rows = std::vector<std::vector<double>>;

DPGEN_KERNEL void row_length(DPGEN_IN const Rows& u, DPGEN_OUT Rows& v, int ny) {
  for (int j = 0; j < ny; ++j) {
    const auto& r = u[j];
    // CHECK-DAG: row_references.cpp:[[@LINE+1]]:32: error: the length of a row (u[j].size()) is outside the kernel subset
    for (int i = 0; i < (int)r.size(); ++i)
      v[j][i] = r[i];
  }
}

DPGEN_KERNEL void data_row(DPGEN_IN const Rows& u, DPGEN_OUT Rows& v, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    // CHECK-DAG: row_references.cpp:[[@LINE+1]]:23: error: row 'r' of 'u' is taken at a data-dependent index
    const auto& r = u[(int)u[0][j]];
    for (int i = 0; i < nx; ++i)
      v[j][i] = r[i];
  }
}

DPGEN_KERNEL void data_column(DPGEN_IN const Rows& u, DPGEN_OUT Rows& v, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const auto& r = u[j];
    for (int i = 0; i < nx; ++i)
      // CHECK-DAG: row_references.cpp:[[@LINE+1]]:17: error: 'r[(int)u[0][i]]' is indexed at a data-dependent column
      v[j][i] = r[(int)u[0][i]];
  }
}

DPGEN_KERNEL void whole_row(DPGEN_IN const Rows& u, DPGEN_OUT Rows& v, int ny) {
  for (int j = 0; j < ny; ++j) {
    const auto& r = u[j];
    auto& w = v[j];
    // CHECK-DAG: row_references.cpp:[[@LINE+1]]:5: error: call to 'std::vector<double>::operator=', which dpgen cannot differentiate
    w = r;
  }
}

// A sum read after its loop (a work array of the adjoint's) beside rows of their own: the
// adjoint's buffers are flat (flat std::vector parameters: tests/styles/vector_sums.cpp).
// CHECK-DAG: row_references.cpp:[[@LINE+1]]:19: error: the sum in 's' (read after the loop that adds to it) in a kernel with rows of their own ('u', a std::vector<std::vector<double>>): pass the arrays as flat std::vector or pointers [dpgen-work-array]
DPGEN_KERNEL void normalized_rows(DPGEN_IN const Rows& u, DPGEN_OUT Rows& v, int nx, int ny) {
  double s = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s += u[j][i] * u[j][i];
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      v[j][i] = u[j][i] / s;
}
