// Minmod slope limiter: a data-dependent if/else assigning a local that is
// declared before it (merged as a conditional), plus a reassigned local.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void minmod_slope(DPGEN_IN const double* q, DPGEN_OUT double* slope, int n,
                               double dx) {
  for (int i = 1; i < n - 1; ++i) {
    double l = q[i] - q[i - 1];
    double r = q[i + 1] - q[i];
    double s;
    if (l * r <= 0.0) {
      s = 0.0;
    } else if (std::fabs(l) < std::fabs(r)) {
      s = l;
    } else {
      s = r;
    }
    s /= dx;
    slope[i] = s;
  }
}
