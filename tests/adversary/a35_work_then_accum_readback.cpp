// adversary: work array stored, then += into it in a later nest, then read in a third nest
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a35_work_then_accum_readback(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) w[i] = a[i] * a[i];
  for (int i = 0; i + 1 < n; ++i) w[i + 1] += a[i];
  for (int i = 0; i < n; ++i) o[i] = w[i] * w[i];
}
