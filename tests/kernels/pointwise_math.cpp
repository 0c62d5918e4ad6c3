// Every supported math function once, pointwise (inputs a in [0.5, 2], b in
// [-1, 1]).
#include "test_kernels.hpp"

#include <algorithm>
#include <cmath>

DPGEN_KERNEL void pointwise_math(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                 DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = std::sqrt(a[i] * a[i] + 1.0) + std::exp(-b[i]) * std::sin(a[i]);
    s += std::log(1.0 + b[i] * b[i]) - std::cos(a[i] * b[i]);
    s += std::pow(std::fabs(b[i]) + 1.0, a[i]) + std::pow(a[i], 3.0);
    double lim = std::max(std::min(b[i], 0.5), -0.5);
    out[i] = s * lim + (b[i] > 0.0 ? std::tanh(a[i]) : -b[i] / a[i]);
  }
}
