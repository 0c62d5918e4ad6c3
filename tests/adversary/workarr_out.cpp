#include "dpgen/annotate.hpp"
DPGEN_KERNEL void workarr_out(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    w[i] = a[i] * a[i];
  for (int i = 1; i < n - 1; ++i)
    out[i] = w[i + 1] * w[i - 1] - w[i];
  for (int i = 0; i < n; ++i)
    w[i] = 2.0 * a[i];
}
