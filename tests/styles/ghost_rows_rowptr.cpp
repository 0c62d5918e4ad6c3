// Ghost rows filled the way a hydro code's boundary routine does it, with
// `double**` row pointers: the first `ng` rows of b copy row 0 of a
// (zero-gradient), the rest average each row with the last one. Reads at the
// constant rows 0 and ny - 1 (issue 20, defect 1: the adjoint of a[0][i] lost
// its row and did not compile).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void ghost_rows_rowptr(DPGEN_IN double** a, DPGEN_OUT double** b, int nx, int ny,
                                    int ng) {
  for (int j = 0; j < ng; ++j)
    for (int i = 0; i < nx; ++i)
      b[j][i] = a[0][i];
  for (int j = ng; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      b[j][i] = 0.5 * (a[j][i] + a[ny - 1][i]) * a[j][i];
}
