// r3: size_t difference in a condition: if (n - i > 2) (never wraps), else branch mirror
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_szt_cond_diff(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    if (n - i > 2) o[i] = a[i + 2] * a[i];
    else o[i] = a[n - 1 - i] * 4.0;
  }
}
