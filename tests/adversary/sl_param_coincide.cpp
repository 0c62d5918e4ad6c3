#include "dpgen/annotate.hpp"
DPGEN_KERNEL void sl_param_coincide(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int m) {
  out[0] = a[0] * a[0];
  out[m] = 3.0 * a[1];
}
