// adversary: arms write different extents of the same output, other entries set first
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_arms_different_extent(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) u[i] = a[i];
    for (int i = 1; i + 1 < n; ++i) u[i] = a[i - 1] * a[i + 1];
  }
}
