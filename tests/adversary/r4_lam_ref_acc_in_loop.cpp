// adversary: [&] lambda reading the accumulator inside its loop (a recurrence)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_ref_acc_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto g = [&]() { return 0.5 * s; };
  for (int i = 0; i < n; ++i) s += g() * a[i];
  out[0] = s;
}
