// Local std::vector work arrays: one made with its length (and a value) is a line buffer
// (tests/styles/vector_buffers.cpp); every other way of making one is refused at the
// declaration, and a read of an element no loop wrote, where the vector's value cannot be
// known to be there, says when it is.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <vector>

// The wall faces keep the vector's 0.0, but the vector is made outside the row loop, where a
// face one row leaves out could hold what an earlier row wrote: refused, with the rule.
DPGEN_KERNEL void walls_made_outside(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                     int ny) {
  std::vector<double> flux(nx + 1, 0.0);
  for (int j = 0; j < ny; ++j) {
    for (int i = 1; i < nx; ++i)
      flux[i] = u[j * nx + i] - u[j * nx + i - 1];
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = flux[i + 1] - flux[i];
    // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:25: error: line buffer 'flux' is read at 'flux[i + 1]'{{.*}}(the value a std::vector is made with is read where no store wrote only when the vector is made inside the loops around all its uses, every loop that writes it before the read fills a known range unconditionally and no loop around the read writes it; else assign the elements the loops leave out, `flux[0] = 0.0;`)
  }
}

// Faces written under a condition on the data: which ones keep the vector's value is not
// known.
DPGEN_KERNEL void faces_under_condition(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::vector<double> flux(n + 1, 0.0);
  for (int i = 1; i < n; ++i)
    if (u[i] > 0.0)
      flux[i] = u[i] * u[i - 1];
  for (int i = 0; i < n; ++i)
    out[i] = flux[i + 1] - flux[i];
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:14: error: line buffer 'flux' is read at 'flux[i + 1]'{{.*}}line {{[0-9]+}} writes it under a condition that may not hold here{{.*}}the value a std::vector is made with is read where no store wrote only when
}

// Made from a list: refused.
DPGEN_KERNEL void from_list(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::vector<double> w = {0.25, 0.5, 0.25};
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:23: error: local std::vector 'w' is in the kernel subset as a line buffer made with its length
  for (int i = 1; i < n - 1; ++i)
    out[i] = w[0] * u[i - 1] + w[1] * u[i] + w[2] * u[i + 1];
}

// A copy of the input: refused.
DPGEN_KERNEL void from_copy(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::vector<double> c(u, u + n);
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:23: error: local std::vector 'c' is in the kernel subset as a line buffer made with its length
  for (int i = 0; i < n; ++i)
    out[i] = c[i] * c[i];
}

// Two dimensions: refused.
DPGEN_KERNEL void nested(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  std::vector<std::vector<double>> t(ny, std::vector<double>(nx));
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:36: error: local array 't' of type 'std::vector<std::vector<double> >' is outside the kernel subset: a line buffer (a local array of more than 64 elements, or of a run-time length) holds float or double values, one dimension
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = u[j * nx + i];
}

// A small array indexed by a counter that is not unrolled: the message names line buffers.
DPGEN_KERNEL void small_work(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double f[32];
  for (int i = 0; i < n; ++i)
    f[i] = u[i] * u[i];
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:7: error: index of local array 'f' must be a constant{{.*}}a work array that loops fill and read is a line buffer, of more than 64 elements or a run-time length (`double f[n];`, `std::vector<double> f(n);`)
  for (int i = 0; i < n; ++i)
    out[i] = f[i];
}

// A pointer into the buffer: refused where it is taken.
DPGEN_KERNEL void pointer_into(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::vector<double> w(n);
  double* wp = w.data();
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:16: error: line buffer 'w' is used here other than by its elements ('w[i]'): a pointer into it, or a call that takes it, is outside the kernel subset
  for (int i = 0; i < n; ++i)
    wp[i] = u[i];
  for (int i = 0; i < n; ++i)
    out[i] = w[i];
}

// A recurrence through the vector: before the loop writes v[i - 1], it holds the vector's
// value, after that the loop's store (the read sees both in turn): refused, not read as the
// value (helper-54 found it read as g[0] in every iteration).
DPGEN_KERNEL void recurrence_from_value(DPGEN_IN const double* u, DPGEN_IN const double* g,
                                        DPGEN_OUT double* r, int n) {
  std::vector<double> v(n, g[0]);
  for (int i = 1; i < n; ++i)
    v[i] = u[i] * v[i - 1];
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:19: error: line buffer 'v' is read at 'v[i - 1]', and no earlier loop of the kernel writes it
  for (int i = 0; i < n; ++i)
    r[i] = v[i];
}

// The same, the store after the read in the loop's body.
DPGEN_KERNEL void store_after_read(DPGEN_IN const double* u, DPGEN_IN const double* g,
                                   DPGEN_OUT double* r, int n) {
  std::vector<double> v(n + 1, g[0]);
  for (int i = 1; i < n; ++i) {
    r[i] = v[i - 1] * u[i];
    // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:12: error: line buffer 'v' is read at 'v[i - 1]', and no earlier loop of {{.*}} writes it
    v[i] = u[i];
  }
}

// A read past the vector's end (undefined in the kernel): refused, not read as the value.
DPGEN_KERNEL void past_the_end(DPGEN_IN const double* u, DPGEN_IN const double* g,
                               DPGEN_OUT double* r, int n) {
  std::vector<double> v(n + 1, g[0]);
  for (int i = 1; i < n; ++i)
    v[i] = u[i] * u[i - 1];
  for (int i = 0; i < n; ++i)
    r[i] = v[i + 2] * u[i];
  // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:12: error: line buffer 'v' is read at 'v[i + 2]' (elements 2 to n + 1)
}

// The recurrence read into a local first: the same refusal (the read is in a declaration).
DPGEN_KERNEL void recurrence_through_local(DPGEN_IN const double* u, DPGEN_IN const double* g,
                                           DPGEN_OUT double* r, int n) {
  std::vector<double> v(n, g[0]);
  for (int i = 1; i < n; ++i) {
    const double a = v[i - 1];
    // CHECK-DAG: vector_buffers.cpp:[[@LINE-1]]:22: error: line buffer 'v' is read at 'v[i - 1]', and no earlier loop of the kernel writes it
    v[i] = u[i] * a;
  }
  for (int i = 0; i < n; ++i)
    r[i] = v[i];
}
