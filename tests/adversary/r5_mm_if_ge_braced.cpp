// adversary: if (e >= m) { m = e; } with a body local
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_if_ge_braced(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -0.3;
  for (int i = 0; i < n; ++i)
    { const double e = a[i] + b[i] * b[i]; if (e >= m) { m = e; } }
  out[0] = std::exp(0.5 * m);
}
