// adversary: if (i == n - 1 && flag) with a parameter flag
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_flag_conj(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  out[0] = 0.0;
  for (int i = 0; i < n; ++i)
    if (i == n - 1 && flag) out[0] = a[i] * a[i];
}
