#include "dpgen/annotate.hpp"
DPGEN_KERNEL void rowarr_nx(DPGEN_IN const double (*a)[8], DPGEN_OUT double (*b)[8], int ny, int nx) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx - 1; ++i)
      b[j][i] = a[j][i - 1] * a[j][i + 1] + (j > 0 ? a[j - 1][i] : 0.0);
}
