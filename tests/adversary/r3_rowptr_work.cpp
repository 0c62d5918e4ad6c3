// r3: double** work array (w) read by a later nest at j - 1
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_rowptr_work(DPGEN_IN double** u, DPGEN_OUT double** w, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) w[j][i] = u[j][i] * u[j][i];
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[j][i] = w[j][i] - w[j - 1][i] * u[j][i];
}
