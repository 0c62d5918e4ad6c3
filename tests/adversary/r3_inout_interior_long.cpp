// r3: DPGEN_INOUT, interior only with long counter, ends pass through
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_inout_interior_long(DPGEN_INOUT double* u, DPGEN_IN const double* c, long n) {
  for (long i = 1; i < n - 1; ++i) u[i] = std::exp(-c[i - 1] * c[i + 1]) * u[i];
}
