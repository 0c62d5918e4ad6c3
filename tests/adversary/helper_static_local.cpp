#include "dpgen/annotate.hpp"
static double g(double x) {
  static double scale = 2.0;
  return scale * x * x;
}
DPGEN_KERNEL void helper_static_local(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = g(a[i]);
}
