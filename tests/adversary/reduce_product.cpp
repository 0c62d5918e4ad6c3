#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_product(DPGEN_IN const double* a, DPGEN_OUT double* p, int n) {
  p[0] = 1.0;
  for (int i = 0; i < n; ++i)
    p[0] = p[0] * a[i];
}
