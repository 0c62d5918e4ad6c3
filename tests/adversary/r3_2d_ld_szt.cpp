// r3: 2D with a leading dimension ld (size_t), x offset, rows counted down
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_2d_ld_szt(DPGEN_IN const double* u, DPGEN_OUT double* o, std::size_t nx, std::size_t ny, std::size_t ld) {
  for (std::size_t j = ny; j-- > 0;)
    for (std::size_t i = 1; i < nx; ++i)
      o[j * ld + i] = u[j * ld + i] * u[j * ld + i - 1];
}
