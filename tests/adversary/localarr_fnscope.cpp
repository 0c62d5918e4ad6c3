#include "dpgen/annotate.hpp"
DPGEN_KERNEL void localarr_fnscope(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double v[3];
  for (int i = 1; i < n - 1; ++i) {
    for (int m = 0; m < 3; ++m)
      v[m] = a[i - 1 + m] * a[i - 1 + m];
    out[i] = v[2] - v[0] + v[1] * a[i];
  }
}
