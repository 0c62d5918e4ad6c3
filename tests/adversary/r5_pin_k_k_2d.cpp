// adversary: if (i == k && j == k) in 2D with k a parameter
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_k_k_2d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny, int k) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (i == k && j == k) out[0] = a[j * nx + i] * a[j * nx + i];
}
