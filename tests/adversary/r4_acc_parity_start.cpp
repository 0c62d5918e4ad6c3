// adversary: accumulator over a moving parity loop inside a triangle
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_parity_start(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int j = 0; j < n; ++j) {
    double s = 0;
    for (int i = j % 2; i <= j; i += 2) s += a[i] * a[j - i];
    r[j] = s;
  }
}
