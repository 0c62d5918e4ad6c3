// std::span parameters (C++20), by value: std::span<const double> inputs,
// std::span<double> outputs, sizes from .size(), a periodic wrap.
#include "dpgen/annotate.hpp"

#include <cstddef>
#include <span>

DPGEN_KERNEL void span_advect(DPGEN_IN std::span<const double> q, DPGEN_IN std::span<const double> c,
                              DPGEN_OUT std::span<double> qn, double dt) {
  const std::size_t n = q.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t im = i == 0 ? n - 1 : i - 1;
    qn[i] = q[i] - dt * c[i] * (q[i] - q[im]);
  }
}
