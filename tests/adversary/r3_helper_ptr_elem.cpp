// r3: void helper with a double* out-parameter called with &o[i + 1]
#include "dpgen/annotate.hpp"
static void put(double* r, double v) { *r = v * v - v; }
DPGEN_KERNEL void r3_helper_ptr_elem(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n - 1; ++i) put(&o[i + 1], a[i]);
}
