#include "dpgen/annotate.hpp"
static double f(double x, double y) {
  x = x * y;
  y = y + x;
  return x * y;
}
DPGEN_KERNEL void helper_param_mod(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double t = a[i];
    out[i] = f(t, b[i]) + t;
  }
}
