// r3: void helper with a double& out-parameter bound to an output element o[i] (not a local)
#include "dpgen/annotate.hpp"
static void set(double& r, double v, double w) { r = v * w + v; }
DPGEN_KERNEL void r3_helper_ref_elem(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) set(o[n - 1 - i], a[i], a[n - 1 - i]);
}
