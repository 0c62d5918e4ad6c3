// r3: work array then a mirror read of it (unsigned n)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_work_mirror(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) w[i] = a[i] * a[i];
  for (unsigned i = 0; i < n; ++i) o[i] = w[n - 1 - i] * a[i];
}
