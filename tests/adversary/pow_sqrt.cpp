#include "dpgen/annotate.hpp"
#include <cmath>
DPGEN_KERNEL void pow_sqrt(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = std::pow(a[i], b[i]) + std::pow(b[i], 3) + std::sqrt(a[i] * a[i] + 1.0) + std::exp(std::tanh(b[i]));
}
