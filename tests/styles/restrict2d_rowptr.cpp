// Multigrid full-weighting restriction, vertex-centred: coarse point (J, I)
// sits on fine point (2J, 2I). Grids as `double**` row pointers, as codes
// that allocate rows separately pass them.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void restrict2d_rowptr(DPGEN_IN double** fine, DPGEN_OUT double** coarse, int ncx,
                                    int ncy) {
  for (int J = 1; J < ncy - 1; ++J)
    for (int I = 1; I < ncx - 1; ++I) {
      int i = 2 * I, j = 2 * J;
      coarse[J][I] = 0.25 * fine[j][i] +
                     0.125 * (fine[j][i - 1] + fine[j][i + 1] + fine[j - 1][i] + fine[j + 1][i]) +
                     0.0625 * (fine[j - 1][i - 1] + fine[j - 1][i + 1] + fine[j + 1][i - 1] +
                               fine[j + 1][i + 1]);
    }
}
