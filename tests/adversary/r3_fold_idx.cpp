// r3: read at the distance to the nearer end, a[std::min(i, n - 1 - i)] (folded mirror), long
#include "dpgen/annotate.hpp"
#include <algorithm>
DPGEN_KERNEL void r3_fold_idx(DPGEN_IN const double* a, DPGEN_OUT double* o, long n) {
  for (long i = 0; i < n; ++i) o[i] = a[std::min(i, n - 1 - i)] * a[i] + a[std::max(i, n - 1 - i)];
}
