// Loops written as `while` loops that count, the way C codes often do: the counter set before
// the loop and stepped by the last statement of the body, or counted down by the condition
// (`while (i-- > 0)`). dpgen reads each as the for loop it is (tool/lib/lower_while.cpp).
#include "dpgen/annotate.hpp"

#include <cstddef>

// FTCS heat step; the counter stepped by `i++` at the end of the body.
DPGEN_KERNEL void while_heat1d(DPGEN_IN const double* u, DPGEN_OUT double* u_new, int n, double r) {
  int i = 1;
  while (i < n - 1) {
    u_new[i] = u[i] + r * (u[i - 1] - 2.0 * u[i] + u[i + 1]);
    i++;
  }
}

// Counted down by the condition: an unsigned counter, a body of one statement.
DPGEN_KERNEL void while_countdown(DPGEN_IN const double* u, DPGEN_OUT double* v, std::size_t n,
                                  double s) {
  std::size_t i = n;
  while (i-- > 1)
    v[i] = s * u[i] * u[i - 1];
}

// Two cells per iteration (`i += 2`); the counter declared C89 style and assigned its start.
DPGEN_KERNEL void while_pairs(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  int i;
  i = 0;
  while (i + 1 < n) {
    const double a = u[i], b = u[i + 1];
    v[i] = a * b;
    v[i + 1] = a - b * b;
    i += 2;
  }
}

// A 2D five-point stencil with both loops `while` loops, the inner counter declared in the
// outer loop's body.
DPGEN_KERNEL void while_laplace2d(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny,
                                  double h) {
  int j = 1;
  while (j < ny - 1) {
    int i = 1;
    while (i < nx - 1) {
      const int c = j * nx + i;
      out[c] = (u[c - 1] + u[c + 1] + u[c - nx] + u[c + nx] - 4.0 * u[c]) / (h * h) + u[c] * u[c];
      ++i;
    }
    ++j;
  }
}

// A sum read after its loop; the counter counts down by `--k` from n - 1 to 0.
DPGEN_KERNEL void while_energy(DPGEN_IN const double* u, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  int k = n - 1;
  while (k >= 0) {
    s += u[k] * u[k];
    --k;
  }
  e[0] = 0.5 * s;
}

// NAS MG's resid (tests/styles/line_buffers.cpp, mg_resid) with `while` loops over the planes
// and rows and a nonlinear operator: the line buffers, declared before the loops, get one row
// per iteration of both `while` loops around their uses.
#define WHILE_LINE 130
DPGEN_KERNEL void while_resid(DPGEN_IN const double* u, DPGEN_IN const double* v,
                              DPGEN_OUT double* r, int n1, int n2, int n3) {
  double u1[WHILE_LINE], u2[WHILE_LINE];
  int i3 = 1;
  while (i3 < n3 - 1) {
    int i2 = 1;
    while (i2 < n2 - 1) {
      for (int i1 = 0; i1 < n1; i1++) {
        u1[i1] = u[(i3 * n2 + i2 - 1) * n1 + i1] + u[(i3 * n2 + i2 + 1) * n1 + i1];
        u2[i1] = u[((i3 - 1) * n2 + i2) * n1 + i1] * u[((i3 + 1) * n2 + i2) * n1 + i1];
      }
      for (int i1 = 1; i1 < n1 - 1; i1++)
        r[(i3 * n2 + i2) * n1 + i1] = v[(i3 * n2 + i2) * n1 + i1] -
                                      u1[i1] * (u2[i1 - 1] + u2[i1 + 1]) -
                                      0.5 * u[(i3 * n2 + i2) * n1 + i1] * u1[i1 + 1];
      ++i2;
    }
    ++i3;
  }
}

// The step in parentheses, and by a macro that parenthesizes (`((c) += 1)`).
#define WHILE_ADVANCE(c) ((c) += 1)
DPGEN_KERNEL void while_paren_steps(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                    DPGEN_OUT double* w, int n) {
  int i = 0;
  while (i < n - 1) {
    v[i] = u[i + 1] * u[i];
    (++i);
  }
  int k = 1;
  while (k < n) {
    w[k] = u[k - 1] - u[k] * u[k];
    WHILE_ADVANCE(k);
  }
}

// A flat index carried through a nest of `while` loops (C codes' `idx++` in the inner loop),
// skipping the ghost cells of each row (`k = k + 2` after the inner loop).
DPGEN_KERNEL void while_running_index(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                      int ny) {
  int k = nx + 1;
  int j = 1;
  while (j < ny - 1) {
    int i = 1;
    while (i < nx - 1) {
      out[k] = u[k + 1] - 2.0 * u[k] + u[k - 1] + u[k] * u[k + nx];
      ++k;
      ++i;
    }
    k = k + 2;
    ++j;
  }
}

// Two counters stepped at the end of the body, the one the condition tests last.
DPGEN_KERNEL void while_two_counters(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  int i = 0, j = 1;
  while (i < n - 1) {
    v[i] = u[j] * u[j] - u[i];
    ++j;
    ++i;
  }
}

// Steps written out: the condition's counter stepped before another counter (`++i; ++j;`),
// `k = k + 1`, and a for loop stepping by `m = m + 2`.
DPGEN_KERNEL void while_assign_steps(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                     DPGEN_OUT double* w, DPGEN_OUT double* x, int n) {
  int i = 0, j = 1;
  while (i < n - 1) {
    v[i] = u[j] - u[i] * u[i];
    ++i;
    ++j;
  }
  int k = 0;
  while (k < n) {
    w[k] = u[k] * u[n - 1 - k];
    k = k + 1;
  }
  for (int m = 0; m + 1 < n; m = m + 2)
    x[m] = u[m] + u[m + 1] * u[m];
}

// Counted down by the condition in the other ways C codes write it: `i--` as a truth value,
// `k-- >= 1` (unsigned), `--m >= 0` (the step before the test), `0 < j--`, `p-- != 0`, and a for
// loop whose condition is `q--`.
DPGEN_KERNEL void while_countdown_forms(DPGEN_IN const double* u, DPGEN_OUT double* a,
                                        DPGEN_OUT double* b, DPGEN_OUT double* c,
                                        DPGEN_OUT double* d, DPGEN_OUT double* e,
                                        DPGEN_OUT double* f, int n, std::size_t nu) {
  int i = n;
  while (i--)
    a[i] = u[i] * u[i];
  std::size_t k = nu;
  while (k-- >= 1)
    b[k] = 3.0 * u[k] * u[k] * u[k];
  int m = n - 1;
  while (--m >= 0)
    c[m] = u[m] * u[m + 1];
  int j = n;
  while (0 < j--)
    d[j] = 1.0 / (1.0 + u[j] * u[j]);
  int p = n;
  while (p-- != 0)
    e[p] = 0.5 * u[p] * u[p];
  for (int q = n; q--;)
    f[q] = u[q] - 2.0 * u[q] * u[q] * u[q];
}
