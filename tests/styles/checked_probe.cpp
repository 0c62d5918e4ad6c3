// Kernels whose reach into an array depends on the data, as users write them:
// a gather through an index array (unstructured meshes, particle lists), a
// read one cell over where a mask says so, a clamped semi-Lagrangian departure
// point (C89 counters), an upwind choice that reads a[i - 1] from i = 0 where
// the velocity is negative (a user's boundary bug), and a row sum that adds
// only cells above a threshold (an accumulator, kept by dpgen in an array of
// sums). Their checked entry points (<kernel>_adjoint_checked) cannot bound
// these reads from the loop bounds; they run the kernel's loops once with each
// such index checked, so a short array throws exactly when the data reaches
// past its end, and never lets the adjoint read or write out of bounds.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void gather_by_index(DPGEN_IN const double* a, const int* idx, DPGEN_OUT double* out,
                                  int n) {
  for (int i = 0; i < n; ++i)
    out[i] = 2.0 * a[idx[i]] + a[i];
}

DPGEN_KERNEL void masked_shift(DPGEN_IN const double* a, DPGEN_IN const double* mask,
                               DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (mask[i] > 0.0)
      out[i] = a[i + 1] * a[i];
    else
      out[i] = a[i];
  }
}

DPGEN_KERNEL void departure_c89(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                                DPGEN_OUT double* q_next, int n, double dt) {
  int i, i0;
  double x, w;
  for (i = 0; i < n; i++) {
    x = i - dt * vel[i];
    if (x < 0.0)
      x = 0.0;
    i0 = (int)x;
    w = x - i0;
    q_next[i] = (1.0 - w) * q[i0] + w * q[i0 + 1];
  }
}

DPGEN_KERNEL void upwind_from_zero(DPGEN_IN const double* a, DPGEN_IN const double* u,
                                   DPGEN_OUT double* out, int n, double c) {
  for (int i = 0; i < n; ++i)
    out[i] = u[i] > 0.0 ? a[i] - c * u[i] * (a[i + 1] - a[i]) : a[i] - c * u[i] * (a[i] - a[i - 1]);
}

DPGEN_KERNEL void thresholded_row_sums(DPGEN_IN const double* a, DPGEN_OUT double* s, int nx,
                                       int ny, double t) {
  for (int j = 0; j < ny; ++j) {
    double acc = 0.0;
    for (int i = 0; i < nx; ++i)
      if (a[j * nx + i] > t)
        acc += a[j * nx + i] * a[j * nx + i + 1];
    s[j] = acc;
  }
}

// A global table of four weights read at the cell's index: n > 4 reads past it.
static const double weights4[4] = {0.5, 1.0, 1.5, 2.0};

DPGEN_KERNEL void global_weights(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i] * weights4[i];
}

// A shift in cells computed from a real value (a distance over a spacing), read from a
// parameter array: the checked entry point defines `c` (reading `shift[0]` only once its size is
// checked) to compute `m` and the range of `a` it reaches.
DPGEN_KERNEL void shift_by_distance(DPGEN_IN const double* a, const double* shift,
                                    DPGEN_OUT double* out, int n, double h) {
  double c = shift[0] / h;
  int m = (int)c;
  for (int i = 0; i < n; ++i)
    out[i] = 2.0 * a[i + m];
}

// Rates by material, a global the gradient reaches (DPGEN_IN), and a constant table of
// weights, both read at a material index per cell: a material index past 2 (3) reads past
// the global's (the table's) end; the checked entry point's probe takes each global's place.
DPGEN_IN double g_rate[3] = {0.5, 1.0, 2.0};
static const double kind_weight[4] = {1.0, 0.75, 0.5, 0.25};

DPGEN_KERNEL void rate_by_material(DPGEN_IN const double* a, const int* material,
                                   DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = g_rate[material[i]] * a[i] * kind_weight[material[i] + 1];
}
