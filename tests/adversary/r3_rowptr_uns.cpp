// r3: double** 5-point interior with size_t sizes and counters
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_rowptr_uns(DPGEN_IN double** u, DPGEN_OUT double** o, std::size_t nx, std::size_t ny) {
  for (std::size_t j = 1; j + 1 < ny; ++j)
    for (std::size_t i = 1; i + 1 < nx; ++i)
      o[j][i] = u[j][i] * (u[j][i - 1] + u[j][i + 1] + u[j - 1][i] + u[j + 1][i]);
}
