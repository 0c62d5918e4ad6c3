// corpus: form=window expect=accept
// A learned 1D filter: correlation with differentiable weights w[m - i + d]
// over a window clipped at the ends, then tanh (a convolution layer written
// as a stencil).
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

DPGEN_KERNEL void correlate1d(DPGEN_IN const double* u, DPGEN_IN const double* w,
                              DPGEN_OUT double* out, int n, int d) {
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    for (int m = std::max(0, i - d); m <= std::min(n - 1, i + d); ++m)
      s += w[m - i + d] * u[m];
    out[i] = std::tanh(s);
  }
}
