// Pointer locals: a pointer into a flat array parameter, made where it is declared and
// indexed after, is accepted (tests/styles/pointer_locals.cpp); one that changes, one made
// without a pointer into a parameter, one into a row-pointer array or a local array, and
// one used where a parameter is needed are not. Every error of the file is reported in
// one run, and no file is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void row_advanced(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  const double* row = a;
  for (int j = 0; j < ny; ++j) {
    b[j] = row[0];
    row += nx;
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:5: error: pointer 'row' is changed after its declaration; dpgen follows a pointer fixed where it is declared: declare another ('const double* next = row + nx;') or index this one [dpgen-pointer]
  }
}

DPGEN_KERNEL void row_reassigned(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const double* row = a + j * nx;
    if (j > 0)
      row = a;
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:7: error: pointer 'row' is changed after its declaration
    b[j] = row[0];
  }
}

DPGEN_KERNEL void row_incremented(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  const double* p = a + 0;
  for (int i = 0; i < n; ++i) {
    b[i] = *p;
    ++p;
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:7: error: {{.*}}'p'
  }
}

DPGEN_KERNEL void into_row_pointers(DPGEN_IN double** a, DPGEN_OUT double* b, int n) {
  const double* first = &a[0][1];
  // CHECK: pointer_locals.cpp:[[@LINE-1]]:17: error: pointer 'first' must be initialised
  for (int i = 0; i < n; ++i)
    b[i] = first[i];
}

DPGEN_KERNEL void into_local_array(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  double w[3] = {0.25, 0.5, 0.25};
  const double* mid = w + 1;
  // CHECK: pointer_locals.cpp:[[@LINE-1]]:17: error: pointer 'mid' must be initialised
  for (int i = 1; i < n - 1; ++i)
    b[i] = mid[-1] * a[i - 1] + mid[0] * a[i] + mid[1] * a[i + 1];
}

DPGEN_KERNEL void into_output_scalar(DPGEN_IN const double* a, DPGEN_OUT double& e, int n) {
  double* p = &e + 0;
  // CHECK: pointer_locals.cpp:[[@LINE-1]]:11: error: pointer 'p' must be initialised
  for (int i = 0; i < n; ++i)
    *p += a[i];
}

DPGEN_KERNEL void compared(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const double* row = a + j * nx;
    b[j] = row != a ? row[0] : 0.0;
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:12: error: {{.*}}'row'
  }
}

// Rows (`double (*)[8]`) made from a pointer local or a helper's pointer parameter bound to
// `a + 8`: their offset is no whole row of the parameter's flat index; refused (they were
// accepted with the offset dropped before the review of 2026-12-01).
DPGEN_KERNEL void rows_from_pointer(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  const double* a1 = a + 8;
  const double(*u)[8] = reinterpret_cast<const double(*)[8]>(a1);
  // CHECK: pointer_locals.cpp:[[@LINE-1]]:17: error: pointer 'u' to arrays is made from pointer 'a1'; make it from the array parameter 'a' itself [dpgen-pointer]
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      b[j * nx + i] = u[j][i] * u[j][i];
}

namespace {
void block(const double* p, double* q, int nx, int rows) {
  const double(*u)[8] = reinterpret_cast<const double(*)[8]>(p);
  // CHECK: pointer_locals.cpp:[[@LINE-1]]:17: error: pointer 'u' to arrays is made from pointer 'p'; make it from the array parameter 'a' itself [dpgen-pointer]
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < nx; ++i)
      q[j * nx + i] = u[j][i] * u[j][i];
}
} // namespace

DPGEN_KERNEL void rows_in_helper(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  block(a + 8, b, nx, ny - 1);
}

// References: a const reference to an input's element is a local of its value
// (tests/styles/pointer_locals.cpp); a reference to an output's element (which a later
// store changes), to a local, or a non-const one is refused.
DPGEN_KERNEL void ref_to_output(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    const double& bi = b[i];
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:19: error: reference 'bi' is outside the kernel subset but for a const reference to an element of an input ('const double& bi = u[i];'); copy the value ('const double bi = ...;') or index the array where it is used [dpgen-pointer]
    b[i] = bi * a[i];
  }
}

DPGEN_KERNEL void ref_to_local(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double x = a[i];
    const double& y = x;
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:19: error: reference 'y' is outside the kernel subset
    x = 2.0 * x;
    b[i] = y;
  }
}

DPGEN_KERNEL void ref_writable(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double& out = b[i];
    // CHECK: pointer_locals.cpp:[[@LINE-1]]:13: error: reference 'out' is outside the kernel subset
    out = a[i] * a[i];
  }
}
