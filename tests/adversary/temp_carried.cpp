#include "dpgen/annotate.hpp"
DPGEN_KERNEL void temp_carried(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t = 0;
  for (int i = 0; i < n; ++i) {
    out[i] = t * a[i];
    t = a[i];
  }
}
