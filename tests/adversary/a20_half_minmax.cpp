// adversary: int local half = n/2 in bounds/indices, std::min/max clamped reads
#include "dpgen/annotate.hpp"

#include <algorithm>
DPGEN_KERNEL void a20_half_minmax(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  int half = n / 2;
  for (int i = 0; i < half; ++i) o[i] = a[2 * i] * a[std::min(2 * i + 1, n - 1)];
  for (int i = half; i < n; ++i) o[i] = a[std::max(i - 3, 0)] * a[i];
}
