// adversary: for (j = 0; j < n; j += 2) { K[j] = f; K[j + 3] = g; }: never the same element (parity)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_stride2_no_overlap_odd_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; j += 2) {
    K[j + 3] = std::sin(a[j]);
    K[j] = a[j] * a[j];
  }
}
