// adversary: count-down loop: K[j] = f; K[j + 1] = g; now the K[j + 1] of iteration j - 1... wins
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_countdown(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = n - 1; j >= 0; --j) {
    K[j] = a[j] * b[j];
    K[j + 1] = std::sin(a[j]) + b[j];
  }
}
