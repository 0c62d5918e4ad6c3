// adversary: C89 counter reused across nests, work array, n > i, i + 1 < n
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a13_c89_reuse(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  int i;
  for (i = 0; n > i; i++) w[i] = a[i] * a[i];
  for (i = 1; i + 1 < n; i++) o[i] = w[i - 1] + w[i + 1] - 2.0 * w[i];
}
