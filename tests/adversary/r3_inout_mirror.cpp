// r3: DPGEN_INOUT pointwise update reading another input mirrored (size_t n)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_inout_mirror(DPGEN_INOUT double* u, DPGEN_IN const double* c, std::size_t n, double dt) {
  for (std::size_t i = 0; i < n; ++i) u[i] += dt * c[n - 1 - i] * u[i] * u[i];
}
