#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_ptr_star(DPGEN_IN const double* a, DPGEN_OUT double* loss, int n) {
  *loss = 0;
  for (int i = 0; i < n; ++i)
    *loss += a[i] * a[i];
  *loss = *loss * 0.5;
}
