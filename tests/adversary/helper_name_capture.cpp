#include "dpgen/annotate.hpp"
static double get(const double* u, int i) {
  int k = i + 1;
  return u[k] * u[i];
}
static double twice(double k) { double i = 2.0 * k; return i; }
DPGEN_KERNEL void helper_name_capture(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int k = 0; k < n - 2; ++k) {
    int i = k + 1;
    out[k] = twice(get(a, i)) + get(a, k);
  }
}
