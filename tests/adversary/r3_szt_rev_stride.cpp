// r3: size_t size, strided mirror read a[2 * (n - 1 - i)] (input holds 2n)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_szt_rev_stride(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) o[i] = a[2 * (n - 1 - i)] * a[2 * i + 1];
}
