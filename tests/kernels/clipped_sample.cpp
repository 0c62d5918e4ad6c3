// Reads that happen only in one arm of a conditional expression: a sample at
// a data-dependent index j that is read only when j is inside the array (so
// the scatter adjoint must not write outside it), and an output written only
// where a bool local holds.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void clipped_sample(DPGEN_IN const double* q, DPGEN_IN const double* a,
                                 const double* mask, DPGEN_OUT double* out,
                                 DPGEN_OUT double* masked, int n) {
  for (int i = 0; i < n; ++i) {
    const double x = i + 2.0 * a[i];
    const double fl = std::floor(x);
    const int j = static_cast<int>(fl);
    const double w = x - fl;
    out[i] = (j >= 0 && j < n - 1) ? (1.0 - w) * q[j] + w * q[j + 1] : 0.0;
    const bool active = mask[i] > 0.5;
    if (active)
      masked[i] = a[i] * q[i];
  }
}
