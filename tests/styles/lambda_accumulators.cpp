// Accumulators updated inside lambdas and helpers, the way C and C++ solvers write a
// reduction: a lambda that captures the sum by reference and adds to it (`auto add =
// [&](double x) { s += x * x; };` called in the loop), a per-row sum, a max through
// std::max, two sums in one lambda called twice per iteration, a lambda that returns early
// before it adds, one written in the loop body, one called through another lambda; a helper
// adding to its `double&` parameter, a C helper adding through `double*` (and one passing
// the pointer on), a template helper, a lambda taking the sum by reference, and helpers
// keeping a max (`m = std::max(m, x)`, `if (x > m) m = x;`), and a lambda that owns the loop
// and sums into its `double&` parameter. Each is the same reduction as
// `s += ...` written in the loop (until 2026-12-01 dpgen rejected them: the update was
// hidden in the callee's body, and the message suggested `s += ...`, what the user wrote).
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

DPGEN_KERNEL void energy_lambda(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  auto add = [&](double x) { s += x * x; };
  for (int i = 0; i < n; ++i)
    add(a[i]);
  e[0] = s;
}
DPGEN_KERNEL void row_sums_lambda(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double s = 1.0;
    auto add = [&](double x) { s += std::sin(x); };
    for (int i = 0; i < nx; ++i)
      add(a[j * nx + i]);
    out[j] = s;
  }
}
DPGEN_KERNEL void max_lambda(DPGEN_IN const double* a, DPGEN_OUT double* m_out, int n) {
  double m = -1e300;
  auto upd = [&](double x) { m = std::max(m, x); };
  for (int i = 0; i < n; ++i)
    upd(a[i] * a[i]);
  m_out[0] = m;
}
DPGEN_KERNEL void moments_lambda(DPGEN_IN const double* a, DPGEN_OUT double* mom, int n) {
  double s = 0.0, q = 0.0;
  auto add = [&](double x) {
    s += x;
    q += x * x;
  };
  for (int i = 0; i < n; ++i) {
    add(a[i]);
    add(0.5 * a[i]);
  }
  mom[0] = s;
  mom[1] = q;
}
DPGEN_KERNEL void positive_lambda(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  auto add = [&](double x) {
    if (x < 0.0)
      return;
    s += x * x;
  };
  for (int i = 0; i < n; ++i)
    add(a[i]);
  e[0] = s;
}
DPGEN_KERNEL void inline_lambda(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    auto add = [&s](double x) { s -= x * x * x; };
    add(a[i]);
  }
  e[0] = s;
}
DPGEN_KERNEL void nested_lambda(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  auto sq = [&](double x) { s += x * x; };
  auto both = [&](double x, double y) {
    sq(x);
    sq(y);
  };
  for (int i = 0; i < n; ++i)
    both(a[i], a[n - 1 - i]);
  e[0] = s;
}

static void add_square(double& acc, double x) { acc += x * x; }

DPGEN_KERNEL void energy_helper(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    add_square(s, a[i]);
  e[0] = s;
}

/* C: the sum through a pointer, and a helper passing the pointer on. */
static void add_sq_c(double* acc, double x) { *acc += x * x; }
static void add_pair_c(double* acc, double x, double y) {
  add_sq_c(acc, x);
  *acc -= 0.25 * y;
}

DPGEN_KERNEL void energy_c89(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  int i;
  double s;
  s = 0.0;
  for (i = 1; i < n; ++i)
    add_pair_c(&s, a[i], a[i - 1]);
  e[0] = s;
}

template <typename T> void accumulate_cube(T& acc, T x) { acc += x * x * x; }

DPGEN_KERNEL void energy_template(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 2.0;
  for (int i = 0; i < n; ++i)
    accumulate_cube(s, a[i]);
  e[0] = s;
}

DPGEN_KERNEL void ref_param_lambda(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0.0;
  auto add = [](double& acc, double x) { acc += std::exp(x); };
  for (int i = 0; i < n; ++i)
    add(s, a[i]);
  e[0] = s;
}

static void keep_max(double& m, double x) { m = std::max(m, x); }
static void keep_min_if(double& m, double x) {
  if (x < m)
    m = x;
}

DPGEN_KERNEL void range_helpers(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  double hi = -1e300, lo = 1e300;
  for (int i = 0; i < n; ++i) {
    keep_max(hi, a[i]);
    keep_min_if(lo, a[i] * a[i]);
  }
  r[0] = hi;
  r[1] = lo;
}

// A lambda that owns the loop and sums into its `double&` parameter, per row.
DPGEN_KERNEL void row_norms_ref(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  auto add_row = [&](double& acc, int j) {
    for (int i = 0; i < nx; ++i)
      acc += a[j * nx + i] * a[j * nx + i];
  };
  for (int j = 0; j < ny; ++j) {
    double r = 1.0;
    add_row(r, j);
    out[j] = std::sqrt(r);
  }
}
