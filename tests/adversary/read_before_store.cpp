#include "dpgen/annotate.hpp"
DPGEN_KERNEL void read_before_store(DPGEN_IN const double* a, DPGEN_OUT double* o1, DPGEN_OUT double* o2, int n) {
  for (int i = 0; i < n; ++i) {
    o2[i] = o1[i] + a[i];
    o1[i] = a[i] * a[i];
  }
}
