// adversary: two accumulators sharing a loop with a store
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_acc_two_share_store(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                         DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  double s = 0, t = 0;
  for (int i = 0; i < n; ++i) {
    s += a[i] * b[i];
    u[i] = a[i] * a[i] - b[i];
    t += std::sin(b[i]) * a[i];
  }
  out[0] = s * t;
  out[1] = s - t * t;
}
