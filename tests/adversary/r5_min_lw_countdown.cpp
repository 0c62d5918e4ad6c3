// adversary: MINIMAL: later writer in a loop counting down: iteration j - 1 runs after j, so K[j + 1] of iteration j - 1... the adjoint credits K[j] (ascending order assumed)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r5_min_lw_countdown(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = n - 1; j >= 0; --j) {
    K[j] = a[j];
    K[j + 1] = b[j];
  }
}
