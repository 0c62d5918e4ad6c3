// corpus: form=window expect=accept
// A moving average over a window of runtime half-width d, written as codes
// write it: for (m = i - d; m <= i + d; ++m).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void box_filter(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, int d) {
  const double inv = 1.0 / (2 * d + 1);
  for (int i = d; i < n - d; ++i) {
    double s = 0.0;
    for (int m = i - d; m <= i + d; ++m)
      s += u[m];
    out[i] = s * inv;
  }
}
