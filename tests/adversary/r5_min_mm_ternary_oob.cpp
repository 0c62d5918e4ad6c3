// adversary: MINIMAL: the element of a max is an index-guarded ternary reading a[i - 1]: the adjoint's cell range starts at -1 and adds 0.0 to a_adj[-1] (heap out-of-bounds write)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_min_mm_ternary_oob(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, i == 0 ? 0.0 : a[i - 1]);
  out[0] = m;
}
