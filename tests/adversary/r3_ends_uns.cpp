// r3: straight-line end stores with unsigned n (they meet at n = 1) and an interior loop in between
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_ends_uns(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 1; i + 1 < n; ++i) o[i] = a[i - 1] * a[i + 1];
  o[0] = a[0] * a[n - 1];
  o[n - 1] = 2.0 * a[n - 1] * a[0] + a[0];
}
