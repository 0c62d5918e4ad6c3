#include "dpgen/annotate.hpp"
static const double kW[3] = {0.25, 0.5, 0.25};
DPGEN_KERNEL void global_array(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = kW[0] * a[i - 1] + kW[1] * a[i] * a[i] + kW[2] * a[i + 1];
}
