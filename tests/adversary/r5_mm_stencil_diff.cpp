// adversary: max |u[i+1] - u[i]| (each element in two differences)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_stencil_diff(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double g = 0.0;
  for (int i = 0; i + 1 < n; ++i) g = fmax(g, fabs(u[i + 1] - u[i]));
  out[0] = g * g;
}
