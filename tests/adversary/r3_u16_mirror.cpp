// r3: std::uint16_t size (promotes to int) with a mirror read
#include "dpgen/annotate.hpp"
#include <cstdint>
DPGEN_KERNEL void r3_u16_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, std::uint16_t n) {
  for (int i = 0; i < n; ++i) o[i] = a[n - 1 - i] * a[i];
}
