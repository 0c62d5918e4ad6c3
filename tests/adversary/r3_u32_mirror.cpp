// r3: std::uint32_t size and counter (a typedef of unsigned) with a mirror read
#include "dpgen/annotate.hpp"
#include <cstdint>
DPGEN_KERNEL void r3_u32_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, std::uint32_t n) {
  for (std::uint32_t i = 0; i < n; ++i) o[i] = a[n - 1 - i] * a[i] + a[n - 1 - i];
}
