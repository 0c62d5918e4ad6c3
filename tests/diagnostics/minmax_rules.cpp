// Min/max reductions (tests/styles/minmax_reductions.cpp) that are not:
// one into an output element the kernel never set before the loop (its start
// would be the caller's value, which the adjoint does not have), an arg-max
// index tracked beside the maximum, a maximum read inside its own loop, and
// a variable that takes a max and a min in turn.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void no_start(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  for (int i = 0; i < n; ++i)
    *err = fmax(*err, fabs(r[i]));
  // CHECK: minmax_rules.cpp:[[@LINE-1]]:5: error: the max reduction into '*err' in this loop starts from the value it has before the loop, which the kernel does not set
}

DPGEN_KERNEL void argmax(DPGEN_IN const double* r, DPGEN_OUT double* out, int n) {
  double m = r[0];
  int im = 0;
  for (int i = 1; i < n; ++i)
    if (r[i] > m) {
      // CHECK: minmax_rules.cpp:[[@LINE-1]]:16: error: 'm' is declared outside the loop and assigned inside it, and read here before it is assigned in this iteration
      m = r[i];
      im = i;
    }
  out[0] = m * im;
  // CHECK: minmax_rules.cpp:[[@LINE-1]]:12: error: 'm' is read after the loop that assigns it
}

DPGEN_KERNEL void read_inside(DPGEN_IN const double* r, DPGEN_OUT double* out, int n) {
  double m = 0;
  for (int i = 0; i < n; ++i) {
    m = fmax(m, r[i]);
    // CHECK: minmax_rules.cpp:[[@LINE-1]]:14: error: 'm' is declared outside the loop
    out[i + 1] = m;
  }
  out[0] = m;
}

DPGEN_KERNEL void max_then_min(DPGEN_IN const double* r, DPGEN_OUT double* out, int n) {
  double m = 0;
  for (int i = 0; i < n; ++i) {
    m = fmax(m, r[i]);
    // CHECK: minmax_rules.cpp:[[@LINE-1]]:14: error: 'm' is declared outside the loop
    m = fmin(m, 2 * r[i]);
  }
  out[0] = m;
}

// err[0] reduces, but the loop also writes err[i], which may be err[0]:
// only elements at other constant indices are apart from the target.
DPGEN_KERNEL void element_and_field(DPGEN_IN const double* u, DPGEN_OUT double* err, int n) {
  err[0] = 0.0;
  for (int i = 1; i < n; ++i) {
    err[0] = fmax(err[0], u[i]);
    err[i] = u[i] * u[i];
  }
  // CHECK: minmax_rules.cpp:[[@LINE-2]]:5: error: output 'err' may be written twice in one iteration
}

// A helper that is not a max of its two parameters is no update.
static double not_a_max(double a, double b) { return a > b ? a : 2.0 * b; }

DPGEN_KERNEL void helper_not_max(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i)
    m = not_a_max(m, u[i]);
  // CHECK: minmax_rules.cpp:[[@LINE-1]]:19: error: 'm' is declared outside the loop and assigned inside it
  out[0] = m;
}

// A float max helper on a double reduction would round it: no update.
static float fmx(float a, float b) { return a > b ? a : b; }

DPGEN_KERNEL void helper_rounds(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double m = -1e30;
  for (int i = 0; i < n; ++i)
    m = fmx(m, u[i]);
  // CHECK: minmax_rules.cpp:[[@LINE-1]]:13: error: 'm' is declared outside the loop and assigned inside it
  out[0] = m;
}
