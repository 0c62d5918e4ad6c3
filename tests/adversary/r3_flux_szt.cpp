// r3: flux accumulation rhs[i] += f; rhs[i + 1] -= f with size_t counter (output n + 1)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_flux_szt(DPGEN_IN const double* a, DPGEN_OUT double* r, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    double f = a[i] * a[i + 1];
    r[i] += f;
    r[i + 1] -= f;
  }
}
