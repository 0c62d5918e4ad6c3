// A switch whose cases each end in 'break' (or continue/return) is lowered to
// if/else arms (tests/styles/switch_cases.cpp). What is not accepted: a case
// that falls through into the next, a 'break' that leaves a case early from
// inside an if, and a case range (a GNU extension).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void falls_through(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  for (int i = 0; i < n; ++i) {
    double s = u[i];
    switch (kind) {
    // CHECK-DAG: switch.cpp:[[@LINE+1]]:5: error: a case that falls through into the next is outside the kernel subset; end each case with 'break' (cases that share their statements are labels of one case: 'case 1: case 2: ...') [dpgen-unsupported]
    case 0:
      s *= 2.0;
    case 1:
      s *= u[i];
      break;
    }
    v[i] = s;
  }
}

DPGEN_KERNEL void early_break(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  for (int i = 0; i < n; ++i) {
    double s = u[i];
    switch (kind) {
    case 0:
      if (s > 0.0)
        // CHECK-DAG: switch.cpp:[[@LINE+1]]:9: error: a 'break' ends its case only as the case's last statement; put what follows it under an if/else [dpgen-unsupported]
        break;
      s = -s;
      break;
    default:
      s = 0.0;
    }
    v[i] = s * u[i];
  }
}

DPGEN_KERNEL void case_range(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  for (int i = 0; i < n; ++i) {
    double s = u[i];
    switch (kind) {
    // CHECK-DAG: switch.cpp:[[@LINE+1]]:5: error: a case label is one integer constant
    case 0 ... 3:
      s *= 2.0;
      break;
    }
    v[i] = s * u[i];
  }
}
