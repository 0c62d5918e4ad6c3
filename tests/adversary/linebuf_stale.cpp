#include "dpgen/annotate.hpp"
DPGEN_KERNEL void linebuf_stale(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double buf[16];
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx - j; ++i)
      buf[i] = a[j * nx + i];
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = buf[i] * 2.0;
  }
}
