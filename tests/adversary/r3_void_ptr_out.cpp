// r3: void helper with double* out-parameter called with &f
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
static void upwind(double l, double r, double u, double* f) {
  if (u > 0) *f = u * l;
  else *f = u * r;
}
DPGEN_KERNEL void r3_void_ptr_out(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n; ++i) {
    double f;
    upwind(a[i - 1], a[i], a[i] - 0.1, &f);
    o[i] = f * a[n - i];
  }
}
