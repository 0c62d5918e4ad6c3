// adversary: sequential nests: += then = (= wins), = on all then = on interior
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a31_mixed_nests_last_wins(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) r[i] += a[i] * a[i];
  for (int i = 0; i < n; ++i) r[i] = a[i] * 2.0;
  for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  for (int i = 1; i < n - 1; ++i) u[i] = a[i] * 7.0;
}
