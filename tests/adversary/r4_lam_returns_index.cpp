// adversary: lambda computing an index, used in a subscript
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_returns_index(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto wrap = [n](int i) { return (i + n) % n; };
  for (int i = 0; i < n; ++i) out[i] = u[wrap(i - 1)] * u[wrap(i + 1)];
}
