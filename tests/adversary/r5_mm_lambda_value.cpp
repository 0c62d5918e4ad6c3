// adversary: lambda max m = mx(m, e)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_lambda_value(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto mx = [](double x, double y) { return x > y ? x : y; };
  double m = -3.0;
  for (int i = 0; i < n; ++i) m = mx(m, std::sin(a[i]));
  out[0] = m * m;
}
