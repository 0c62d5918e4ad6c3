// r3: void helper writing its pointer out-parameter as r[0] (not *r); two results through r[0] and q[0]
#include "dpgen/annotate.hpp"
static void two(double x, double y, double* r, double* q) {
  r[0] = x * y;
  q[0] = x - y * y;
}
DPGEN_KERNEL void r3_void_ptr_index0(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    double p, m;
    two(a[i], a[n - 1 - i], &p, &m);
    o[i] = p * m;
  }
}
