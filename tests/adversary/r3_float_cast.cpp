// r3: float kernel with (float) casts of ints and a double literal in the value
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_float_cast(DPGEN_IN const float* a, DPGEN_OUT float* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = a[i] * (float)(n - i) * 0.25f + 0.5 * a[n - 1 - i] * a[i];
}
