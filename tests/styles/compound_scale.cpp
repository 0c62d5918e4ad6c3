// Finite-volume flux scaled in place after it is stored: `f[i] = ...;` then
// `f[i] *= area` and `f[i] /= vol` on the same element in the same
// iteration (the element's value is the iteration's own store, read back).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void compound_scale(DPGEN_IN const double* q, DPGEN_IN const double* area,
                                 DPGEN_IN const double* vol, DPGEN_OUT double* f, int n) {
  for (int i = 1; i < n; ++i) {
    f[i] = 0.5 * (q[i] + q[i - 1]) * (q[i] - q[i - 1]);
    f[i] *= area[i];
    f[i] -= 0.1 * q[i];
    f[i] /= vol[i] + 1.5;
  }
}
