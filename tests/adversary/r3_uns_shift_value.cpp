// r3: unsigned value wrap through an unsigned local: d = i - 1 is 4294967295 at i = 0 (scaled to ~4.29)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_uns_shift_value(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    unsigned d = i - 1;
    o[i] = 1e-9 * d * a[i] + a[i] * a[i];
  }
}
