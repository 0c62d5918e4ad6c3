#include "dpgen/annotate.hpp"
DPGEN_KERNEL void flux_acc(DPGEN_IN const double* a, DPGEN_IN const double* k, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = 0;
  for (int i = 0; i + 1 < n; ++i) {
    double f = k[i] * (a[i + 1] - a[i]) * a[i];
    out[i] += f;
    out[i + 1] -= f;
  }
}
