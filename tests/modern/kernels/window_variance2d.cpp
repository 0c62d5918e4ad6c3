// corpus: form=window expect=accept
// Local variance over a (2d+1)^2 window (an image/field roughness measure):
// a 4-deep nest, two window loops inside the cell loops, two sums.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void local_variance(DPGEN_IN const double* a, DPGEN_OUT double* var, int nx, int ny,
                                 int d) {
  const double inv = 1.0 / ((2 * d + 1) * (2 * d + 1));
  for (int j = d; j < ny - d; ++j)
    for (int i = d; i < nx - d; ++i) {
      double s = 0.0, s2 = 0.0;
      for (int jj = j - d; jj <= j + d; ++jj)
        for (int ii = i - d; ii <= i + d; ++ii) {
          const double v = a[jj * nx + ii];
          s += v;
          s2 += v * v;
        }
      const double mean = s * inv;
      var[j * nx + i] = s2 * inv - mean * mean;
    }
}
