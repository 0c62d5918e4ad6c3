// Sums into an output spelled out, as much C and Fortran-ported code writes
// them: `*acc = *acc + a[i] * b[i]`, `out[j] = out[j] + x - y`, `s[0] = e +
// s[0]`, through a view and in a void helper. Each is the `+=` of its terms
// to the adjoint; the forward forms add them as C++ does (one by one, a float
// element and a double term as doubles, rounded once). A store to the element
// earlier in the same iteration makes it a read back instead
// (compound_scale.cpp). Refused forms: tests/diagnostics/spelled_sums.cpp.
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

#include <cmath>

// A dot product into a scalar output by pointer.
DPGEN_KERNEL void dot_spelled(DPGEN_IN const double* a, DPGEN_IN const double* b,
                              DPGEN_OUT double* acc, int n) {
  *acc = 0.0;
  for (int i = 0; i < n; ++i)
    *acc = *acc + a[i] * b[i];
}

// Row sums with a subtracted term: a chain of two terms.
DPGEN_KERNEL void rowsum_spelled(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    out[j] = 0.0;
    for (int i = 1; i < nx; ++i)
      out[j] = out[j] + a[j * nx + i] * a[j * nx + i] - 0.5 * std::sin(a[j * nx + i - 1]);
  }
}

// `e + x` and `x - e` into two outputs, C89 counters.
DPGEN_KERNEL void two_sums_c89(DPGEN_IN const double* a, DPGEN_OUT double* s, DPGEN_OUT double* t,
                               int n) {
  int i;
  s[0] = 1.0;
  t[0] = 0.0;
  for (i = 0; i < n; i++) {
    s[0] = a[i] * a[i] + s[0];
    t[0] = t[0] - std::exp(0.5 * a[i]);
  }
}

// A chain in float: each term a float, as the output.
DPGEN_KERNEL void column_sums_float(DPGEN_IN const float* a, DPGEN_IN const float* w,
                                    DPGEN_OUT float* out, int nx, int ny) {
  for (int i = 0; i < nx; ++i)
    out[i] = 0.0f;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      out[i] = out[i] + w[j] * a[j * nx + i] - 0.25f * a[j * nx + i] * a[j * nx + i];
}

// Float outputs and a float accumulator with double terms (the literals): C++ adds each in
// double and rounds the sum once to float, and so do the tangent and the parallel forward.
DPGEN_KERNEL void column_sums_mixed(DPGEN_IN const float* a, DPGEN_OUT float* out,
                                    DPGEN_OUT float* total, DPGEN_OUT float* mean, int nx, int ny) {
  for (int i = 0; i < nx; ++i)
    out[i] = 0.0f;
  total[0] = 0.0f;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      out[i] = out[i] + a[j * nx + i] - 0.1 * a[j * nx + i] * a[j * nx + i];
      total[0] += 0.3 * a[j * nx + i];
    }
  for (int j = 0; j < ny; ++j) {
    float s = 0.0f;
    for (int i = 0; i < nx; ++i)
      s += 0.7 * a[j * nx + i];
    mean[j] = s / nx;
  }
}

// Through views: row j's sum into s(j, 0), beside products of neighbours into r
// (one column fewer than q).
DPGEN_KERNEL void view_row_sums(DPGEN_IN grid::View2D<const double> q,
                                DPGEN_OUT grid::View2D<double> r,
                                DPGEN_OUT grid::View2D<double> s) {
  for (int j = 0; j < q.rows(); ++j) {
    s(j, 0) = q(j, 0);
    for (int i = 1; i < q.cols(); ++i) {
      r(j, i - 1) = q(j, i) * q(j, i - 1);
      s(j, 0) = s(j, 0) + std::cos(q(j, i));
    }
  }
}

// A void helper that adds to an output element.
static void add_to(double* out, int k, double v) { out[k] = out[k] + v; }

DPGEN_KERNEL void helper_adds(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = 0.0;
  for (int i = 1; i < n - 1; ++i) {
    add_to(out, i - 1, 0.5 * a[i]);
    add_to(out, i + 1, 0.5 * a[i] * a[i]);
  }
}

// A read back: the element stored earlier in the iteration, then spelled-out added to.
DPGEN_KERNEL void store_then_add(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                 DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] * a[i];
    out[i] = out[i] + std::sin(b[i]) + out[i] * b[i];
  }
}

// Local sums spelled out as chains: a double total over the grid (stored to a float) and a
// float sum per row with double terms (the literals: C++ adds each in double and rounds the
// row's sum once).
DPGEN_KERNEL void local_sum_chains(DPGEN_IN const float* a, DPGEN_OUT float* energy,
                               DPGEN_OUT float* rows, int nx, int ny) {
  double s = 0.0;
  for (int j = 0; j < ny; ++j) {
    float r = 1.0f;
    for (int i = 0; i < nx; ++i) {
      const float v = a[j * nx + i];
      s = s + v - 0.5 * v * v;
      r = r - 0.25 * std::sin(v) + v * v;
    }
    rows[j] = r * r;
  }
  energy[0] = s;
}

// The sum in the middle of its chain, `s = e + s - f`: C++ adds e first, and e + s is s + e
// bit for bit; a compound e (`x * x + 0.5 * y + s`) is one term, added whole. A chain cast to
// the sum's own type, `(float)(...)`, is the assignment's own conversion.
DPGEN_KERNEL void mid_chain_sums(DPGEN_IN const float* a, DPGEN_IN const float* b,
                                 DPGEN_OUT float* total, DPGEN_OUT float* cols, int nx, int ny) {
  float s = 0.0f;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const float x = a[j * nx + i], y = b[j * nx + i];
      s = x * x + 0.5 * y + s - x * y;
    }
  total[0] = s;
  for (int i = 0; i < nx; ++i) {
    cols[i] = 0.0f;
    for (int j = 0; j < ny; ++j)
      cols[i] = (float)(a[j * nx + i] * b[j * nx + i] + cols[i] - 0.25 * a[j * nx + i]);
  }
}
