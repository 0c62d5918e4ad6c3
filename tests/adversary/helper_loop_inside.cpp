#include "dpgen/annotate.hpp"
static double sum3(const double* u, int i) {
  double s = 0;
  for (int m = -1; m <= 1; ++m)
    s += u[i + m] * (m + 2);
  return s;
}
DPGEN_KERNEL void helper_loop_inside(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = sum3(a, i) * a[i];
}
