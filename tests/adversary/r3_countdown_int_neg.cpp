// r3: int countdown to 0 with i >= 0, reads at i and n - 1 - i, store at n - 1 - i
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_countdown_int_neg(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = n - 1; i >= 0; --i) o[n - 1 - i] = a[i] * a[n - 1 - i] * 0.5;
}
