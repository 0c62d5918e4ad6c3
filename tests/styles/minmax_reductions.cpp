// minmax_reductions (tests/styles/): min/max reductions written as solver
// codes write them (issue 20): the residual's max norm (into a local and into
// `*error`), a CFL time step, row maxima with a MAX macro, if-updates (C89
// counters), two updates in one iteration, column minima into an output row,
// and updates with initializer lists of several terms (`m = std::max({m, x,
// y})`).
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#define MAX(a, b) ((a) > (b) ? (a) : (b))

// The residual's infinity norm, as Jacobi codes check convergence.
DPGEN_KERNEL void red_maxnorm(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  double e = 0.0;
  for (int i = 0; i < n; ++i)
    e = fmax(e, fabs(r[i]));
  err[0] = e;
}

// A CFL step: dt = cfl * dx / max |u| + c (std::max, a local of the body).
DPGEN_KERNEL void red_cfl(DPGEN_IN const double* u, DPGEN_OUT double* dt, double c, double dx,
                          int n) {
  double smax = 1e-12;
  for (int i = 0; i < n; ++i) {
    const double s = std::fabs(u[i]) + c;
    smax = std::max(smax, s);
  }
  dt[0] = 0.5 * dx / smax;
}

// Row maxima of a 2D field with the MAX macro, started from the row's first.
DPGEN_KERNEL void red_rowmax_macro(DPGEN_IN const double* a, DPGEN_OUT double* rowmax, int nx,
                                   int ny) {
  for (int j = 0; j < ny; ++j) {
    double m = a[j * nx];
    for (int i = 1; i < nx; ++i)
      m = MAX(m, a[j * nx + i] * a[j * nx + i]);
    rowmax[j] = m;
  }
}

// if-update min over a 2D interior (C89 counters), scaled after the loops.
DPGEN_KERNEL void red_min_if_c89(DPGEN_IN const double* h, DPGEN_OUT double* hmin, int nx,
                                 int ny) {
  int i, j;
  double m = 1.0e30;
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      if (h[j * nx + i] - h[j * nx + i - 1] < m)
        m = h[j * nx + i] - h[j * nx + i - 1];
  hmin[0] = 2.0 * m;
}

// Two updates in one iteration and a second, separate max (of a squared
// value) in the same kernel; float.
DPGEN_KERNEL void red_two_updates_float(DPGEN_IN const float* a, DPGEN_IN const float* b,
                                        DPGEN_OUT float* out, int n) {
  float m = a[0];
  float q = 0.0f;
  for (int i = 0; i < n; ++i) {
    m = std::max(m, a[i]);
    m = std::max(b[i], m);
    q = fmaxf(q, a[i] * b[i]);
  }
  out[0] = m + 3.0f * q;
}

// The residual's max norm into an output scalar, as C solvers write it
// (`*error = fmax(*error, ...)`), over a 2D interior.
DPGEN_KERNEL void red_jacobi_error(DPGEN_IN const double* u, DPGEN_IN const double* f,
                                   DPGEN_OUT double* error, int nx, int ny, double h) {
  *error = 0.0;
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const double r = f[j * nx + i] - (4.0 * u[j * nx + i] - u[j * nx + i - 1] -
                                        u[j * nx + i + 1] - u[(j - 1) * nx + i] -
                                        u[(j + 1) * nx + i]) / (h * h);
      *error = fmax(*error, fabs(r));
    }
}

// Column minima into an output row, an if-update per element.
DPGEN_KERNEL void red_colmin_out(DPGEN_IN const double* a, DPGEN_OUT double* colmin, int nx,
                                 int ny) {
  for (int i = 0; i < nx; ++i) {
    colmin[i] = a[i];
    for (int j = 1; j < ny; ++j)
      if (a[j * nx + i] < colmin[i])
        colmin[i] = a[j * nx + i];
  }
}

// Start values the library computes (std::numeric_limits, -HUGE_VAL), an
// if-update with a second condition, and an element that exists only from
// the second iteration on (a read under `i == 0 ? ... : a[i - 1]`).
DPGEN_KERNEL void red_limits_and_cond(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double lo = std::numeric_limits<double>::max();
  double hi = -HUGE_VAL;
  double prev = std::numeric_limits<double>::lowest();
  for (int i = 0; i < n; ++i) {
    lo = std::min(lo, a[i] * a[i] + 0.5);
    if (a[i] > hi && i % 2 == 0)
      hi = a[i];
    prev = fmax(prev, i == 0 ? -1.0 : a[i - 1] * a[i]);
  }
  out[0] = lo;
  out[1] = hi;
  out[2] = prev;
}

// The range of a field in one sweep, into two elements of one output (a
// max into err[0] and a min into err[1], one with an if-update).
DPGEN_KERNEL void red_range_two_elements(DPGEN_IN const double* u, DPGEN_OUT double* err, int n) {
  err[0] = -1e300;
  err[1] = 1e300;
  for (int i = 0; i < n; ++i) {
    err[0] = std::fmax(err[0], u[i] * u[i]);
    if (u[i] < err[1])
      err[1] = u[i];
  }
}

// A C code's own max and min helpers (the idiom before <math.h> had fmax),
// one called as `m = dmax(m, e)`, the other with the target second.
static inline double dmax(double a, double b) { return a > b ? a : b; }
static inline double dmin(double x, double y) { return (y < x) ? y : x; }

DPGEN_KERNEL void red_user_helpers(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double hi = -1e300, lo = 1e300;
  for (int i = 1; i < n; ++i) {
    double g = u[i] - u[i - 1];
    hi = dmax(hi, g * g);
    lo = dmin(0.5 * g, lo);
  }
  out[0] = hi;
  out[1] = lo;
}

// A max reduction into a local and a min reduction into an output element, each updated with
// an initializer list of terms (each term an update of its own).
DPGEN_KERNEL void red_list_updates(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                   DPGEN_OUT double* hi, DPGEN_OUT double* lo, int n) {
  double m = -1.0e300;
  lo[0] = 1.0e300;
  for (int i = 0; i < n; ++i) {
    m = std::max({m, a[i] * b[i], a[i] + b[i]});
    lo[0] = std::min({a[i] - b[i], lo[0], std::sin(a[i])});
  }
  hi[0] = m * m;
}
