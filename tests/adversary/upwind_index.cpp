#include "dpgen/annotate.hpp"
DPGEN_KERNEL void upwind_index(DPGEN_IN const double* a, DPGEN_IN const double* v, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    int k = v[i] > 0 ? i - 1 : i + 1;
    out[i] = v[i] * (a[i] - a[k]);
  }
}
