// adversary: accumulator over i = 1 + (j - 2) % 3, step 3 (start -1 +1 = 0 at j = 1)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_negative_mod_start_acc(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  for (int j = 0; j < m; ++j) {
    double s = 0;
    for (int i = 2 + (j - 2) % 3; i < n; i += 3) s += a[j * n + i] * a[j * n + i];
    r[j] = s;
  }
}
