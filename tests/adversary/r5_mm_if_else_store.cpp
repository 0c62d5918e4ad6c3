// adversary: if (e > m) m = e; else u[i] = m; (the else arm reads the running max)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_if_else_store(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) {
    u[i] = 0.0;
    if (a[i] > m) m = a[i];
    else u[i] = a[i] * 2.0;
  }
  out[0] = m;
}
