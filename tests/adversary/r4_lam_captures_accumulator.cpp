// adversary: lambda [&] reading an accumulator
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_captures_accumulator(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += u[i] * u[i];
  auto scale = [&](int i) { return u[i] * s; };
  for (int i = 0; i < n; ++i) out[i] = scale(i) + s;
}
