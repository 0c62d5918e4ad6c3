// adversary: std::max<double>(m, e) and std::fmax
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_std_max_template_arg(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -4.0, q = -4.0;
  for (int i = 0; i < n; ++i) {
    m = std::max<double>(m, a[i] * a[i]);
    q = std::fmax(q, -a[i]);
  }
  out[0] = m + q * q;
}
