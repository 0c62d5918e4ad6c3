#include "dpgen/annotate.hpp"
double g_coef = 3.0;
DPGEN_KERNEL void global_scalar_mut(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = g_coef * a[i] * a[i];
}
