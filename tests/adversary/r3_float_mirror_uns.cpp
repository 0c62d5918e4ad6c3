// r3: float kernel, unsigned n, mirror read
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_float_mirror_uns(DPGEN_IN const float* a, DPGEN_OUT float* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = a[n - 1 - i] * a[i] + 0.5f * a[i];
}
