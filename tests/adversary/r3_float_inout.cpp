// r3: float DPGEN_INOUT update with an unsigned countdown and mirrored coefficient
#include "dpgen/annotate.hpp"
#include <cmath>
DPGEN_KERNEL void r3_float_inout(DPGEN_INOUT float* u, DPGEN_IN const float* c, unsigned n) {
  for (unsigned i = n; i-- > 0;) u[i] = u[i] + 0.5f * c[n - 1 - i] * std::tanh(u[i]);
}
