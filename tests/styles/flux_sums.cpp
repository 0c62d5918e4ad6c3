// Contributions to one element added in several `+=` statements, as flux
// codes add each face's in turn (one under a condition). dpgen merges them
// into one store for the adjoint; the tangent's primal adds them in the
// kernel's order, ((r + a) + b) + c, for the same bits, not r + (a + b + c).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void face_sums(DPGEN_IN const double* u, DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) {
    r[i] += u[i + 1] - u[i];
    r[i] += u[i + 2] * u[i + 1];
    if (i % 2 == 0)
      r[i] += 0.1 * u[i];
    r[i] += u[i] / 3.0;
  }
}

// The sum of a row into its first element, the same way.
DPGEN_KERNEL void row_totals(DPGEN_IN const double* u, DPGEN_OUT double* t, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      t[j] += u[j * nx + i] * u[j * nx + i];
      t[j] += 0.5 * u[j * nx + i];
    }
}

// Added to, then set: the element holds the value set (the sum is gone).
DPGEN_KERNEL void add_then_set(DPGEN_IN const double* u, DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) {
    r[i] += u[i] * u[i];
    r[i] = 2.0 * u[i] + u[i] * u[i];
  }
}
