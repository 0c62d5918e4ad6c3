#include "dpgen/annotate.hpp"
static void flux(double l, double r, double& f) { f = l * r; }
DPGEN_KERNEL void helper_ref_out(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n - 1; ++i) {
    double f = 1.0;
    flux(a[i], a[i + 1], f);
    out[i] = f;
  }
}
