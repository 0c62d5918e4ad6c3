// r3: loop stores all, statement after the loop overwrites o[0] and o[n - 1]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_after_loop_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = a[i] * a[i];
  o[0] = a[0] * a[n - 1];
  o[n - 1] = a[n - 1] + 3.0 * a[0];
}
