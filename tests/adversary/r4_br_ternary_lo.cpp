// adversary: loop start chosen by a ternary on a parameter
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_ternary_lo(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  const int lo = flag != 0 ? 1 : 0;
  for (int i = 0; i < n; ++i) u[i] = 0.0;
  for (int i = lo; i < n; ++i) u[i] = a[i] * a[i - lo];
}
