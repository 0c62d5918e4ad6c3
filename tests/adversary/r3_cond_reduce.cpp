// r3: data-conditional reduction into loss[0] and an index-conditional one into loss[1], size_t n
#include "dpgen/annotate.hpp"
#include <cstddef>
DPGEN_KERNEL void r3_cond_reduce(DPGEN_IN const double* a, DPGEN_OUT double* loss, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    if (a[i] > 0) loss[0] += a[i] * a[n - 1 - i];
    if (i + 1 < n) loss[1] -= a[i] * a[i + 1];
  }
}
