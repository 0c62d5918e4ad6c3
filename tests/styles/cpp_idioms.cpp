// Idioms of everyday C++ in stencil code: loops that stop at `i != n` (counting
// up, and down to zero with an unsigned counter), a weight table's length as
// `sizeof(w) / sizeof(w[0])`, the MC limiter written with std::min and
// std::max of initializer lists (the first least or greatest of the list,
// which is what dpgen differentiates: min(min(a, b), c)), and a median filter
// by a sorting network of std::swap.
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

// A smoothing filter from a binomial table; the table's length from sizeof.
DPGEN_KERNEL void binomial_smooth(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  static const double w[] = {0.0625, 0.25, 0.375, 0.25, 0.0625};
  const int taps = sizeof(w) / sizeof(w[0]);
  const int half = taps / 2;
  for (int i = half; i != n - half; ++i) {
    double acc = 0.0;
    for (int k = 0; k != taps; ++k)
      acc += w[k] * u[i - half + k];
    v[i] = acc * acc;
  }
}

// Monotonized-central slopes: zero at an extremum, else the least of 2|dl|, |dl + dr| / 2 and
// 2|dr| with the sign of the central difference; the cell's range from std::max({...}).
DPGEN_KERNEL void mc_slopes(DPGEN_IN const double* q, DPGEN_OUT double* slope,
                            DPGEN_OUT double* top, int n) {
  for (int i = 1; i != n - 1; ++i) {
    const double dl = q[i] - q[i - 1], dr = q[i + 1] - q[i];
    const double mag =
        std::min({2.0 * std::fabs(dl), 0.5 * std::fabs(dl + dr), 2.0 * std::fabs(dr)});
    slope[i] = dl * dr > 0.0 ? (dl + dr > 0.0 ? mag : -mag) : 0.0;
    top[i] = std::max({q[i - 1], q[i], q[i + 1]}) + std::min({q[i]});
  }
}

// Backward differences counted down to zero with an unsigned counter.
DPGEN_KERNEL void backward_diff(DPGEN_IN const float* u, DPGEN_OUT float* d, unsigned n) {
  for (unsigned i = n - 1; i != 0; --i)
    d[i] = u[i] * u[i] - u[i - 1];
}

// A median-of-three filter, sorted by a network of conditional swaps.
DPGEN_KERNEL void median3(DPGEN_IN const double* u, DPGEN_OUT double* m, int n) {
  for (int i = 1; i < n - 1; ++i) {
    double a = u[i - 1], b = u[i], c = u[i + 1];
    if (a > b)
      std::swap(a, b);
    if (b > c)
      std::swap(b, c);
    if (a > b)
      std::swap(a, b);
    m[i] = b * std::fabs(b);
  }
}

// The same network through a helper that orders two values in place (by reference).
static void order2(double& lo, double& hi) {
  if (lo > hi)
    std::swap(lo, hi);
}

DPGEN_KERNEL void median3_helper(DPGEN_IN const double* u, DPGEN_OUT double* m, int n) {
  for (int i = 1; i < n - 1; ++i) {
    double a = u[i - 1], b = u[i], c = u[i + 1];
    order2(a, b);
    order2(b, c);
    order2(a, b);
    m[i] = b * b * a - c; // (the least and the greatest too)
  }
}

// Helpers and an accessor called with arguments left to their defaults.
static double soft_clip(double x, double cap = 2.0, double width = 0.5) {
  return cap * std::tanh(x / (cap * width));
}

struct Column {
  const double* p;
  int nx;
  const double& operator()(int j, int i = 0) const { return p[j * nx + i]; }
};

DPGEN_KERNEL void default_args(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  const Column U{u, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      v[j * nx + i] = soft_clip(u[j * nx + i]) + soft_clip(u[j * nx + i], 1.0) * U(j);
}
