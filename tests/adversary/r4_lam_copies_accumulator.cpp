// adversary: lambda [=] copying an accumulator after its loop
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_copies_accumulator(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) s += u[i] * u[i];
  auto scale = [=](int i) { return u[i] / s; };
  for (int i = 0; i < n; ++i) out[i] = scale(i);
}
