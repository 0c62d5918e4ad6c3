// r3: void helper storing into the output at a mirrored index
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
static void put(double* o, int k, double v, double s) { o[k] = v * s; }
DPGEN_KERNEL void r3_void_store_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) put(o, n - 1 - i, a[i], a[i] + 1.0);
}
