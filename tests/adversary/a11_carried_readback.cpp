// adversary: output written in iteration i read at i-1 in the same nest (carried)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a11_carried_readback(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                       DPGEN_OUT double* v, int n) {
  w[0] = a[0] * a[0];
  for (int i = 1; i < n; ++i) {
    w[i] = a[i] * a[i];
    v[i] = w[i - 1] * a[i];
  }
}
