// r3: += into a mirrored output, unsigned n, two loops accumulate into it
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_accum_rev_uns(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[n - 1 - i] += a[i] * a[i];
  for (unsigned i = 0; i < n; ++i) o[i] += 2.0 * a[n - 1 - i];
}
