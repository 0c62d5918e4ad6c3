// adversary: else-if chain of 3 loop nests on a parameter
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_elseif3(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  } else if (flag == 1) {
    for (int i = 1; i < n; ++i) u[i] = a[i] - a[i - 1] * a[i];
    if (n > 0) u[0] = 0.0;
  } else {
    for (int i = 0; i < n; ++i) u[i] = 3.0 * a[i];
  }
}
