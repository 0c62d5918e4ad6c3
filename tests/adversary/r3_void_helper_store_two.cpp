// r3: void helper storing into two output arrays
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
static void both(double* p, double* q, int i, double v) {
  p[i] = v * v;
  q[i] = -v;
}
DPGEN_KERNEL void r3_void_helper_store_two(DPGEN_IN const double* a, DPGEN_OUT double* p, DPGEN_OUT double* q, int n) {
  for (int i = 0; i < n; ++i) both(p, q, i, a[n - 1 - i] * a[i]);
}
