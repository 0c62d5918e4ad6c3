// r3: void helper reading and modifying a double& that holds a prior value
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
static void relax(double& x, double t) { x = x + 0.5 * (t - x) * t; }
DPGEN_KERNEL void r3_void_ref_inout_local(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    double x = a[i] * a[i];
    relax(x, a[n - 1 - i]);
    relax(x, a[i]);
    o[i] = x;
  }
}
