// r3: void helper *s += v * v called twice with the same local's address
#include "dpgen/annotate.hpp"
static void acc(double* s, double v) { *s += v * v; }
DPGEN_KERNEL void r3_void_ptr_accum(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i + 1 < n; ++i) {
    double s = a[i];
    acc(&s, a[i]);
    acc(&s, a[i + 1]);
    o[i] = s;
  }
}
