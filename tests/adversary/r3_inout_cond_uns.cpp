// r3: DPGEN_INOUT, unsigned countdown, conditional second update
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_inout_cond_uns(DPGEN_INOUT double* u, DPGEN_IN const double* c, unsigned n) {
  for (unsigned i = n; i-- > 0;) {
    u[i] = u[i] * c[i];
    if (i % 2 == 1) u[i] = u[i] * u[i] + c[n - 1 - i];
  }
}
