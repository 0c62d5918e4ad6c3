#include "dpgen/annotate.hpp"
DPGEN_KERNEL void localarr_weights(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double w[3] = {0.25, 0.5, 0.25};
  for (int i = 1; i < n - 1; ++i) {
    double s = 0;
    for (int m = 0; m < 3; m++)
      s += w[m] * a[i - 1 + m] * a[i];
    out[i] = s;
  }
}
