// adversary: banded matvec with band storage A[i*3 + (j-i+1)]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_banded_storage(DPGEN_IN const double* A, DPGEN_IN const double* x,
                                        DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - 1); j < std::min(n, i + 2); ++j) s += A[i * 3 + (j - i + 1)] * x[j] * x[i];
    y[i] = s;
  }
}
