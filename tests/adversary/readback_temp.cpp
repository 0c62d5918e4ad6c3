#include "dpgen/annotate.hpp"
DPGEN_KERNEL void readback_temp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] * a[i];
    double t = out[i];
    if (a[i] > 0)
      t = 2.0 * t;
    out[i] = t + a[i];
  }
}
