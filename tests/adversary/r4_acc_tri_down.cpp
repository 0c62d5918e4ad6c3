// adversary: accumulator in a triangle counting down
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_tri_down(DPGEN_IN const double* a, DPGEN_OUT double* y, int n) {
  for (int i = n - 1; i >= 0; --i) {
    double s = 0.0;
    for (int j = n - 1; j >= i; --j) s += a[j] * a[j - i];
    y[i] = s;
  }
}
