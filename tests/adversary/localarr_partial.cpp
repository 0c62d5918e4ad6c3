#include "dpgen/annotate.hpp"
DPGEN_KERNEL void localarr_partial(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double v[2] = {1.0, 1.0};
  for (int i = 0; i < n; ++i) {
    if (i > 0)
      v[1] = a[i - 1];
    v[0] = a[i];
    out[i] = v[0] * v[1];
  }
}
