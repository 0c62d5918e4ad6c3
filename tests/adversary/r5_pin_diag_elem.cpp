// adversary: if (i == j) d[i] = ... (each element once, on the diagonal)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_diag_elem(DPGEN_IN const double* a, DPGEN_OUT double* d, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j) d[i] = a[j * n + i] * a[j * n + i];
}
