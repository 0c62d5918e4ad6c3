// Binomial smoothing with the weights in a small local array and an inner
// loop over the stencil taps.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void smooth_weights_localarray(DPGEN_IN const double* a, DPGEN_OUT double* out,
                                            int n) {
  const double w[3] = {0.25, 0.5, 0.25};
  for (int i = 1; i < n - 1; ++i) {
    double s = 0.0;
    for (int m = 0; m < 3; ++m)
      s += w[m] * a[i - 1 + m];
    out[i] = s;
  }
}
