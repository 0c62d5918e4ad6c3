#include "dpgen/annotate.hpp"
DPGEN_KERNEL void half_local(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int half = n / 2;
  for (int i = 0; i < half; ++i)
    out[i] = a[2 * i] * a[half + i];
}
