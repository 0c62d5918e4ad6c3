// Range-based for over small local tables, as modern C++ stencil code
// writes weights: a C array with a running offset beside it, a `static
// constexpr std::array` of coefficients read by `const auto&`, a table of
// integer offsets, and a table filled from the inputs in the same iteration
// and then summed with `for (double d : diffs)`. dpgen unrolls each loop
// with the variable bound to one element per copy.
#include "dpgen/annotate.hpp"

#include <array>
#include <cmath>

DPGEN_KERNEL void smooth_running_offset(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  const double w[3] = {0.25, 0.5, 0.25};
  for (int i = 1; i < n - 1; ++i) {
    double s = 0.0;
    int o = -1;
    for (double wk : w) {
      s += wk * a[i + o] * a[i + o];
      ++o;
    }
    b[i] = s;
  }
}

DPGEN_KERNEL void fd4_constexpr_range(DPGEN_IN const double* u, DPGEN_OUT double* du, int n,
                                      double inv_h) {
  static constexpr std::array<double, 5> c{1.0 / 12, -2.0 / 3, 0.0, 2.0 / 3, -1.0 / 12};
  static constexpr std::array<int, 5> off{-2, -1, 0, 1, 2};
  for (int i = 2; i < n - 2; ++i) {
    double s = 0.0;
    int m = 0;
    for (const auto& ck : c) {
      s += ck * std::sin(u[i + off[m]]);
      ++m;
    }
    du[i] = s * inv_h;
  }
}

DPGEN_KERNEL void offsets_table(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const int offsets[4] = {-2, -1, 1, 2};
  for (int i = 2; i < n - 2; ++i) {
    double s = u[i];
    for (int o : offsets)
      s = std::max(s, u[i + o] * u[i]);
    out[i] = s;
  }
}

DPGEN_KERNEL void sum_of_squared_diffs(DPGEN_IN const double* q, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    std::array<double, 2> diffs{};
    diffs[0] = q[i] - q[i - 1];
    diffs[1] = q[i + 1] - q[i];
    double s = 0.0;
    for (double d : diffs)
      s += d * d;
    out[i] = std::sqrt(s + 1e-3);
  }
}
