#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ld_flat(DPGEN_IN const double* a, DPGEN_OUT double* b, int ny, int nx, int ld) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      b[j * ld + i] = a[j * ld + i] * a[j * ld + i];
}
