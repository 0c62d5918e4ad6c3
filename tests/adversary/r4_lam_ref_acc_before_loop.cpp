// adversary: [&] lambda made before the accumulation loop, called after (sees the sum)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_ref_acc_before_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto f = [&](double x) { return s * x; };
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = f(a[0 * n]) + f(2.0);
}
