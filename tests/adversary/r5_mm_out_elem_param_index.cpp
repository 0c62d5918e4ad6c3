// adversary: out[k] = 0; out[k] = fmax(out[k], a[i]); k a parameter
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_out_elem_param_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int k) {
  out[k] = 0.0;
  for (int i = 0; i < n; ++i) out[k] = fmax(out[k], a[i] * a[i]);
}
