// r3 minimal: double** output at a mirrored row; the run-time write-once check tests -R - nx >= 0 and always throws
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_min_rowptr_rev_out(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[ny - 1 - j][i] = u[j][i];
}
