// adversary: work array written only with += then read by a later nest
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a38_accum_only_work(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) r[i] += a[i] * a[i];
  for (int i = 0; i < n; ++i) o[i] = r[i] * a[i];
}
