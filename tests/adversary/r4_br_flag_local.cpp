// adversary: branch on a local copied from the parameter
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_flag_local(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  const bool predict = flag == 0;
  if (predict) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) u[i] = 0.5 * a[i];
  }
}
