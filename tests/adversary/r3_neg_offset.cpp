// r3: negative constant offsets in both store and reads
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_neg_offset(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 3; i < n + 3; ++i) o[i - 3] = a[i - 3] * a[i - 3] + (i > 3 ? a[i - 4] : 0.0);
}
