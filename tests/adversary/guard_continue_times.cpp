#include "dpgen/annotate.hpp"
DPGEN_KERNEL void guard_continue_times(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0 || i == n - 1) {
      out[i] = 0;
      continue;
    }
    out[i] = a[i - 1] * a[i + 1];
    if (a[i] > 0)
      out[i] *= a[i];
  }
}
