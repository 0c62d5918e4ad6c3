#include "dpgen/annotate.hpp"
#include <cmath>
static double lim(double x, double y) {
  if (x * y <= 0)
    return 0;
  if (std::fabs(x) < std::fabs(y)) {
    if (x > 0)
      return x * x;
    return -x * x;
  }
  return y * x;
}
DPGEN_KERNEL void helper_multiret(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = lim(a[i] - a[i - 1], a[i + 1] - a[i]);
}
