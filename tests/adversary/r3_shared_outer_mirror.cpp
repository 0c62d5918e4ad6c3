// r3: shared outer loop, two inner loops into two outputs, second stores mirrored in i
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_shared_outer_mirror(DPGEN_IN const double* u, DPGEN_OUT double* p, DPGEN_OUT double* q, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) p[j * nx + i] = u[j * nx + i] * u[j * nx + i];
    for (int i = 0; i < nx; ++i) q[j * nx + nx - 1 - i] = u[j * nx + i] + p[j * nx + i] * 0.0 + 1.0 * u[j * nx + i] * u[(ny - 1 - j) * nx + i];
  }
}
