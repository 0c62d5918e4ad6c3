// A predicted value bounded by its neighbours with std::clamp (as limiters
// keep a reconstruction within the local extrema), then scaled by a second
// input: the value picked is v, lo or hi, and so is the derivative.
#include "dpgen/annotate.hpp"

#include <algorithm>

DPGEN_KERNEL void clamp_limiter(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double lo = std::min(a[i - 1], a[i + 1]);
    const double hi = std::max(a[i - 1], a[i + 1]);
    out[i] = std::clamp(a[i] + 2.0 * b[i], lo, hi) * b[i];
  }
}
