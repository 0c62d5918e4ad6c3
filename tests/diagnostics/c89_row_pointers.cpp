// Row pointers declared with no value (C89) and assigned at the top of each loop body are
// accepted (tests/styles/c89_row_pointers.cpp). Refused: a use that would see the row of an
// earlier iteration or of before the loop, an assignment in an arm of a condition, a use after
// the loop that assigned it, a pointer stepped from one iteration to the next, and a pointer
// assigned something other than a pointer into an array parameter. Every error of the file
// is reported in one run, once per pointer, and no file is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void carried_row(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  const double* row;
  row = u;
  for (int j = 0; j < ny; j++) {
    v[j] = row[0];
    row = u + j * nx;
    // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:9: error: pointer 'row' is changed here in a loop, holding a value from before the loop's iteration (in the next iteration it would point where this one left it); {{.*}} [dpgen-pointer]
  }
}

DPGEN_KERNEL void used_first(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  const double* row;
  for (int j = 0; j < ny; j++) {
    v[j] = row[1];
    // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:12: error: pointer 'row' is used before it is assigned (in this iteration: a value from an earlier one, or from before the loop, is not followed){{.*}} [dpgen-pointer]
    row = u + j * nx;
  }
}

DPGEN_KERNEL void chosen_in_arm(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                DPGEN_OUT double* v, int n, int k) {
  const double* src = 0;
  if (k > 0)
    src = a;
  // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:9: error: pointer 'src' is changed here in an arm of a condition, a block of its own or a lambda{{.*}} [dpgen-pointer]
  else
    src = b;
  for (int i = 0; i < n; i++)
    v[i] = src[i];
}

DPGEN_KERNEL void used_after_loop(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx,
                                  int ny) {
  const double* last;
  for (int j = 0; j < ny; j++)
    last = u + j * nx;
  for (int i = 0; i < nx; i++)
    v[i] = last[i];
  // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:12: error: pointer 'last' is used before it is assigned {{.*}} [dpgen-pointer]
}

DPGEN_KERNEL void stepped(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  const double* p;
  p = u;
  for (int i = 0; i < n; i++) {
    v[i] = *p;
    p++;
    // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:6: error: pointer 'p' is stepped by '++' (its value carries from one iteration to the next){{.*}} [dpgen-pointer]
  }
}

DPGEN_KERNEL void advanced(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  const double* row;
  for (int j = 0; j < ny; j++) {
    row = u;
    row += j * nx;
    // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:9: error: pointer 'row' is changed here by '+=' (its value carries from one iteration to the next){{.*}} [dpgen-pointer]
    v[j] = row[0];
  }
}

DPGEN_KERNEL void set_by_lambda(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx,
                                int ny) {
  const double* row;
  auto point_at = [&](int j) { row = u + j * nx; };
  // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:36: error: pointer 'row' is changed here in an arm of a condition, a block of its own or a lambda{{.*}} [dpgen-pointer]
  for (int j = 0; j < ny; j++) {
    point_at(j);
    v[j] = row[0];
  }
}

DPGEN_KERNEL void into_local(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  double w[3] = {0.25, 0.5, 0.25};
  const double* mid;
  mid = w + 1;
  // CHECK-DAG: c89_row_pointers.cpp:[[@LINE-1]]:9: error: pointer 'mid' must be assigned a pointer into an array parameter of the kernel ('mid = a + j * nx;', '&a[k]') [dpgen-pointer]
  for (int i = 1; i < n - 1; ++i)
    v[i] = mid[-1] * u[i - 1] + mid[0] * u[i] + mid[1] * u[i + 1];
}
