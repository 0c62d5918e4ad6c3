// adversary: void helper updating *m through a pointer: if (e > *m) *m = e;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline void upd_max(double* m, double e) { if (e > *m) *m = e; }
DPGEN_KERNEL void r5_mm_helper_ptr_update(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) upd_max(&m, a[i] * a[i] - a[i]);
  out[0] = m * m;
}
