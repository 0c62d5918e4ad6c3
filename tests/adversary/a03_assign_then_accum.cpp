// adversary: = in one nest, += / -= into the same output in a later nest (flux accumulation on top of a source)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a03_assign_then_accum(DPGEN_IN const double* a, DPGEN_IN const double* s,
                                        DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) r[i] = s[i] * s[i];
  for (int i = 0; i + 1 < n; ++i) {
    double f = a[i + 1] * a[i];
    r[i] += f;
    r[i + 1] -= f;
  }
}
