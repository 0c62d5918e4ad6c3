// adversary: the element reads an output stored earlier in the iteration
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_elem_reads_output(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * b[i];
    m = fmax(m, u[i] + 0.5 * u[i] * u[i]);
  }
  out[0] = m;
}
