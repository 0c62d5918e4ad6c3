// r3: periodic via %: a[(i + 1) % n] and a[(i + n - 1) % n]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_mod_idx(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = a[(i + 1) % n] * a[(i + n - 1) % n] + a[i];
}
