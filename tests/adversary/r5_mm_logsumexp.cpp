// adversary: log-sum-exp with the max subtracted
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_logsumexp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -1e30;
  for (int i = 0; i < n; ++i) m = std::max(m, a[i]);
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += std::exp(a[i] - m);
  out[0] = n > 0 ? m + std::log(s) : 0.0;
}
