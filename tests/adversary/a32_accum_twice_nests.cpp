// adversary: += into r in two nests (both contributions count), -= reduction into loss
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a32_accum_twice_nests(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* loss, int n) {
  for (int i = 0; i < n; ++i) r[i] += a[i] * a[i];
  for (int i = 0; i < n; ++i) r[i] += 3.0 * a[i];
  for (int i = 0; i < n; ++i) loss[0] -= a[i] * r[i];
}
