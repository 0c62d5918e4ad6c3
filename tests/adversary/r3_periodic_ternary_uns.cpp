// r3: periodic wrap ternary with unsigned n and counter
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_periodic_ternary_uns(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = a[i == n - 1 ? 0 : i + 1] * a[i == 0 ? n - 1 : i - 1];
}
