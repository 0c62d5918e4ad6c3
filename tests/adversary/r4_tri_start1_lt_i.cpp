// adversary: i from 1, j from 1 to i-1 (i-1 bound written as j <= i - 1)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_start1_lt_i(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n; ++i) {
    double s = a[i];
    for (int j = 1; j <= i - 1; ++j) s += a[j] * a[i - j];
    out[i] = s * s;
  }
}
