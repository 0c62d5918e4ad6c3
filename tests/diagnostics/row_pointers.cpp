// Row pointers (`double** a`, a[j][i]) are accepted; a row used as a value,
// a data-dependent row or column, and more than one level of row pointers
// are not. Every error of the file is reported in one run.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void row_as_value(DPGEN_IN double** a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j)
    out[j] = *a[j];
  // CHECK: row_pointers.cpp:[[@LINE-1]]:14: error: pointer arithmetic is outside the kernel subset
}

DPGEN_KERNEL void row_star(DPGEN_IN double** a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j)
    out[j] = (*a)[j];
  // CHECK: row_pointers.cpp:[[@LINE-1]]:15: error: pointer arithmetic is outside the kernel subset
}

DPGEN_KERNEL void data_column(DPGEN_IN double** a, DPGEN_IN const double* x,
                              DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j) {
    int i0 = (int)x[j];
    out[j] = a[j][i0];
    // CHECK: row_pointers.cpp:[[@LINE-1]]:14: error: row-pointer array 'a' is indexed at a data-dependent row or column
  }
}

DPGEN_KERNEL void three_levels(DPGEN_IN double*** a, DPGEN_OUT double* out, int n) {
  // CHECK: row_pointers.cpp:[[@LINE-1]]:51: error: parameter 'a' ('double ***') has more than one level of row pointers
  for (int j = 0; j < n; ++j)
    out[j] = a[j][j][j];
}
