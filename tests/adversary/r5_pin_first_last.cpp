// adversary: if (i == 0) / if (i == n - 1) diagnostics beside the main store
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_first_last(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* ends, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    if (i == 0) ends[0] = std::exp(a[i]);
    if (i == n - 1) ends[1] = a[i] * a[0];
  }
}
