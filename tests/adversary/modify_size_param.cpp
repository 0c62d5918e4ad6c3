#include "dpgen/annotate.hpp"
DPGEN_KERNEL void modify_size_param(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double dt) {
  n = n - 1;
  dt = dt * 2.0;
  for (int i = 0; i < n; ++i)
    out[i] = dt * a[i + 1] * a[i];
}
