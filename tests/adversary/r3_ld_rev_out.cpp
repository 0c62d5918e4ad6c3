// r3: flat 2D with a pitch ld, rows flipped on store: o[(ny - 1 - j) * ld + i] (image flip); ld >= nx unprovable -> run-time check
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_ld_rev_out(DPGEN_IN const double* u, DPGEN_OUT double* o, int nx, int ny, int ld) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[(ny - 1 - j) * ld + i] = u[j * ld + i] * u[j * ld + i];
}
