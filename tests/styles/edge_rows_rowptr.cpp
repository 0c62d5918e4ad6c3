// One-sided differences at the first and last row of a `double**` field into
// a two-row output: stores and reads at constant rows (e[0][i], e[1][i],
// a[0][i], a[1][i]) on both sides of the adjoint (issue 20, defect 1).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void edge_rows_rowptr(DPGEN_IN double** a, DPGEN_OUT double** e, int nx, int ny,
                                   double inv_h) {
  for (int i = 0; i < nx; ++i) {
    e[0][i] = (a[1][i] - a[0][i]) * inv_h;
    e[1][i] = (a[ny - 1][i] - a[ny - 2][i]) * inv_h * a[ny - 1][i];
  }
}
