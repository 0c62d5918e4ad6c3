// std::vector kernels with work arrays: a vector normalised by its norm (a local sum read
// after its loop, in a later loop) and fluxes stored to one output vector and differenced
// into another (an output a later loop reads), and a prefix of n elements scaled by its mean
// square (an int bound). The adjoint recomputes the work arrays into buffers of its own, from
// the containers' data.
#include "dpgen/annotate.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

DPGEN_KERNEL void vector_normalize(DPGEN_IN const std::vector<double>& a,
                                   DPGEN_OUT std::vector<double>& unit) {
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum_sq += a[i] * a[i];
  const double inv = 1.0 / std::sqrt(sum_sq);
  for (std::size_t i = 0; i < a.size(); ++i)
    unit[i] = a[i] * inv;
}

DPGEN_KERNEL void vector_fluxes(DPGEN_IN const std::vector<double>& u,
                                DPGEN_OUT std::vector<double>& flux,
                                DPGEN_OUT std::vector<double>& du, double dt) {
  const int n = static_cast<int>(u.size());
  for (int i = 0; i + 1 < n; ++i) {
    const double m = 0.5 * (u[i] + u[i + 1]);
    flux[i] = 0.5 * m * m;
  }
  for (int i = 1; i + 1 < n; ++i)
    du[i] = u[i] - dt * (flux[i] - flux[i - 1]);
}

// The first n elements scaled by their mean square (n an int parameter, no larger than the
// vectors: the adjoint and tangent check it against their sizes).
DPGEN_KERNEL void vector_scaled_prefix(DPGEN_IN const std::vector<double>& a,
                                       DPGEN_OUT std::vector<double>& w, int n) {
  double ms = 0.0;
  for (int i = 0; i < n; ++i)
    ms = a[i] * a[i] / n + ms;
  for (int i = 0; i < n; ++i)
    w[i] = a[i] * ms;
}

// Products of neighbours stored under a condition (the last element is not written), then
// read by a later loop: the outputs may be one shorter than the input.
DPGEN_KERNEL void vector_guarded_pairs(DPGEN_IN const std::vector<double>& u,
                                       DPGEN_OUT std::vector<double>& f,
                                       DPGEN_OUT std::vector<double>& g) {
  const int n = static_cast<int>(u.size());
  for (int i = 0; i < n; ++i)
    if (i + 1 < n)
      f[i] = u[i] * u[i + 1];
  for (int i = 0; i + 1 < n; ++i)
    g[i] = 2.0 * f[i] * u[i];
}
