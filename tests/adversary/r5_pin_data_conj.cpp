// adversary: if (i == 0 && a[0] > 0): pinned and data-dependent
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_data_conj(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == 0 && a[i] > 0.0) out[0] = a[i] * a[i];
}
