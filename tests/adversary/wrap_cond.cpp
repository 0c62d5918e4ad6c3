#include "dpgen/annotate.hpp"
DPGEN_KERNEL void wrap_cond(DPGEN_IN const double* a, DPGEN_IN const double* c, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    int ip = i + 1 == n ? 0 : i + 1;
    int im = i == 0 ? n - 1 : i - 1;
    out[i] = c[i] * (a[ip] - 2.0 * a[i] + a[im]) + a[ip] * a[im];
  }
}
