#include "dpgen/annotate.hpp"
DPGEN_KERNEL void localarr_cond(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double v[2] = {0.0, 0.0};
    if (a[i] > 0)
      v[0] = a[i] * b[i];
    else
      v[1] = a[i] - b[i];
    out[i] = v[0] * b[i] + v[1] * v[1];
  }
}
