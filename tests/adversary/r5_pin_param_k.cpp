// adversary: if (i == k) out[0] = ...; k may be outside the loop (then nothing is stored)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_param_k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int k) {
  for (int i = 0; i < n; ++i)
    if (i == k) out[0] = a[i] * a[i] + 1.0;
}
