// adversary: int counter and a double sum in one loop, divided after
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_count_and_sum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int cnt = 0;
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > 0.0) { cnt++; s += a[i] * a[i]; }
  out[0] = cnt > 0 ? s / cnt : 0.0;
}
