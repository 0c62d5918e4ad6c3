// corpus: form=bitops expect=accept
// Red-black Gauss-Seidel half sweep written out of place, as multigrid
// smoothers on GPUs are: the colour test is ((i + j) & 1) == color; cells of
// the other colour are copied.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void rb_half_sweep(DPGEN_IN const double* u, const double* f, DPGEN_OUT double* out,
                                int nx, int ny, int color, double h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int c = j * nx + i;
      if (((i + j) & 1) == color)
        out[c] = 0.25 * (u[c - 1] + u[c + 1] + u[c - nx] + u[c + nx] - h2 * f[c]);
      else
        out[c] = u[c];
    }
}
