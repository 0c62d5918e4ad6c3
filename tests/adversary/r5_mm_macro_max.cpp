// adversary: MAX macro of an expression
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define MAX(x, y) ((x) > (y) ? (x) : (y))

DPGEN_KERNEL void r5_mm_macro_max(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -5.0;
  int i;
  for (i = 0; i < n; i++) m = MAX(m, a[i] * a[i] + b[i]);
  out[0] = m;
}
