#include "dpgen/annotate.hpp"
DPGEN_KERNEL void init_then_acc_nests(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i] * b[i];
  for (int i = 0; i + 1 < n; ++i) {
    double f = a[i + 1] - a[i];
    out[i] -= f * b[i];
    out[i + 1] += f * f;
  }
  for (int i = 1; i < n - 1; ++i)
    out[i] += b[i - 1] * b[i + 1];
}
