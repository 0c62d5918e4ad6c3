// adversary: lambda used in a loop bound
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_called_in_bound(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto last = [n]() { return n - 1; };
  for (int i = 0; i < last(); ++i) out[i] = u[i] * u[i + 1];
}
