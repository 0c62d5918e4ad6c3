// adversary: if (a[i] > m) { m = a[i]; out[1] = b[i]; }: a payload stored under the running max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_argmax_payload(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -5.0;
  out[1] = 0.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m) { m = a[i]; out[1] = b[i]; }
  out[0] = m;
}
