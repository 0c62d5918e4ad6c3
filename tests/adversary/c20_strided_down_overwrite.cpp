// corpus 20: a loop counting down by 2 whose second store is overwritten by
// the next iteration's first (b[i - 2], then b[i] at i - 2): the later writer
// wins, as in the ascending twin. Its adjoint and tangent were accepted with
// a run-time layout check ("rows of length -2") that threw for every n >= 3.
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void c20_strided_down_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = n - 1; i >= 2; i -= 2) {
    b[i] = a[i] * a[i];
    b[i - 2] = 2.0 * a[i - 1];
  }
}
// the ascending twin
DPGEN_KERNEL void c20_strided_up_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i + 2 < n; i += 2) {
    b[i] = a[i] * a[i];
    b[i + 2] = 2.0 * a[i + 1];
  }
}
