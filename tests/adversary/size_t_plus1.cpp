#include "dpgen/annotate.hpp"
#include <cstddef>
DPGEN_KERNEL void size_t_plus1(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n) {
  for (std::size_t i = 0; i + 1 < n; ++i)
    out[i] = a[i + 1] * a[i];
  for (std::size_t i = 2; n > i; i++)
    out[i] += a[i - 2];
}
