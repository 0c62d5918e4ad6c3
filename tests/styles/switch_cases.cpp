// `switch` as solver code writes it: a sweep direction chosen by an enum
// inside the loop nest, a boundary-condition kind on the ends (labels that
// share a case, a case in a block, a default), a three-colour pattern on
// `i % 3` with a case that skips the cell (`continue`). And the condition
// that exposed a printing bug: an `if (a || b)` around a nested if, whose
// guard was printed `a || b && c` (C++ reads a || (b && c)) where the IR
// meant (a || b) && c.
#include "dpgen/annotate.hpp"

enum SweepDir { X_DIR = 0, Y_DIR = 1 };

DPGEN_KERNEL void sweep_switch(DPGEN_IN const double* u, DPGEN_OUT double* f, int nx, int ny,
                               int dir) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      double d;
      switch (dir) {
      case X_DIR:
        d = u[j * nx + i + 1] - u[j * nx + i - 1];
        break;
      case Y_DIR:
        d = u[(j + 1) * nx + i] - u[(j - 1) * nx + i];
        break;
      default:
        d = 0.5 * u[j * nx + i];
      }
      f[j * nx + i] = d * u[j * nx + i];
    }
}

DPGEN_KERNEL void boundary_kinds(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  for (int i = 1; i < n - 1; ++i)
    v[i] = u[i] * u[i];
  switch (kind) {
  case 0: // zero gradient
  case 1:
    v[0] = u[1] * u[1];
    v[n - 1] = u[n - 2] * u[n - 2];
    break;
  case 2: { // fixed value
    v[0] = 0.0;
    v[n - 1] = 0.0;
    break;
  }
  default: // periodic
    v[0] = u[n - 2] * u[1];
    v[n - 1] = u[1] * u[n - 2];
    break;
  }
}

DPGEN_KERNEL void three_colours(DPGEN_IN const double* u, DPGEN_OUT double* w, int n) {
  for (int i = 1; i < n - 1; ++i) {
    switch (i % 3) {
    case 0:
      w[i] = u[i - 1] * u[i + 1];
      break;
    case 1:
      w[i] = u[i] * u[i] * u[i];
      break;
    default:
      continue;
    }
  }
}

DPGEN_KERNEL void or_then_nested(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  for (int i = 0; i < n; ++i) {
    if (kind == 0 || kind == 1) {
      if (i > 2)
        v[i] = u[i] * u[i];
      else
        v[i] = 3.0 * u[i];
    } else {
      v[i] = 2.0 * u[i];
    }
  }
}
