// adversary: a later-writer pair fills a work array that a later loop reads
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_work_array_then_read(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* w, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j) {
    w[j] = a[j] * b[j];
    w[j + 1] = a[j] + b[j];
  }
  for (int i = 0; i < n; ++i) out[i] = w[i] * w[i + 1];
}
