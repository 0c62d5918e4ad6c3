// adversary: ng ghost rows on both sides copied from the nearest interior row
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_ghost_ng(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m, int ng) {
  for (int j = ng; j < m - ng; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][i] * a[j][i];
  for (int j = 0; j < ng; ++j)
    for (int i = 0; i < n; ++i) {
      b[j][i] = a[ng][i];
      b[m - 1 - j][i] = a[m - 1 - ng][i] * 2.0;
    }
}
