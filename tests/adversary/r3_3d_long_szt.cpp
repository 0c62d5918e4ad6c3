// r3: 3D, size_t sizes, long counters, long flat index, z mirrored read
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_3d_long_szt(DPGEN_IN const double* u, DPGEN_OUT double* o, std::size_t nx, std::size_t ny, std::size_t nz) {
  for (long k = 0; k < (long)nz; ++k)
    for (long j = 0; j < (long)ny; ++j)
      for (long i = 0; i < (long)nx; ++i) {
        const long c = (k * (long)ny + j) * (long)nx + i;
        const long m = (((long)nz - 1 - k) * (long)ny + j) * (long)nx + i;
        o[c] = u[m] * u[c] + u[m];
      }
}
