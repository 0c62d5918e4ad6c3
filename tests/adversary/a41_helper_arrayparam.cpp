// adversary: a24 split: helper with array parameter only
#include "dpgen/annotate.hpp"

static double diff(const double* p, int i) { return p[i + 1] - p[i]; }
DPGEN_KERNEL void a41_helper_arrayparam(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = q[i] * diff(q, i - 1) * diff(q, i);
}
