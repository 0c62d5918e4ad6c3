#include "dpgen/annotate.hpp"
DPGEN_KERNEL void wrap_stmt(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    int ip = i + 1;
    if (ip == n)
      ip = 0;
    out[i] = a[ip] * a[i];
  }
}
