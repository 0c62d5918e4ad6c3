// Grid transfers of the cell-centred multigrid in dpgen/solvers/multigrid.hpp: bilinear
// prolongation P, one axis per kernel (P = P_y P_x), and the 2x2 average that
// coarsens a cell-centred coefficient. The restriction is R = P^T / 4, computed
// by the generated adjoints of the two prolongation kernels, so R is exactly
// the transpose of P and the V-cycle stays a symmetric operator.
#include "kernels.hpp"

// Fine cell 2*ic + di sits a quarter of a coarse cell from the centre of coarse
// cell ic, towards its west (di = 0) or east (di = 1) neighbour, so
//   f[2*ic + di] = 3/4 c[ic] + 1/4 c[ic -+ 1].
// Past the first and last coarse cell the neighbour is a ghost:
//   periodic  (self 0, wrap 1):  the cell at the other end;
//   Neumann   (self 1, wrap 0):  c[ic] itself (zero slope at the wall);
//   Dirichlet (self -1, wrap 0): -c[ic] (zero value on the wall face).
DPGEN_KERNEL void mg_prolong_x(DPGEN_IN const double* c, DPGEN_OUT double* f, int nxc, int ny,
                               double west_self, double west_wrap, double east_self,
                               double east_wrap) {
  for (int j = 0; j < ny; ++j)
    for (int ic = 0; ic < nxc; ++ic)
      for (int di = 0; di < 2; ++di) {
        const int row = j * nxc;
        double side;
        if (di == 0)
          side = ic > 0 ? c[row + ic - 1] : west_self * c[row] + west_wrap * c[row + nxc - 1];
        else
          side = ic < nxc - 1 ? c[row + ic + 1] : east_self * c[row + nxc - 1] + east_wrap * c[row];
        f[j * 2 * nxc + 2 * ic + di] = 0.75 * c[row + ic] + 0.25 * side;
      }
}

// The same along y, on rows already prolonged in x (2*nxc cells wide):
//   f[2*jc + dj] = 3/4 c[jc] + 1/4 c[jc -+ 1], ghosts as above.
DPGEN_KERNEL void mg_prolong_y(DPGEN_IN const double* c, DPGEN_OUT double* f, int nxc, int nyc,
                               double south_self, double south_wrap, double north_self,
                               double north_wrap) {
  // Rows are written as 2 * nxc (not a separate width parameter) so that dpgen can
  // prove every fine cell is written once.
  for (int jc = 0; jc < nyc; ++jc)
    for (int dj = 0; dj < 2; ++dj)
      for (int i = 0; i < 2 * nxc; ++i) {
        const int last = (nyc - 1) * 2 * nxc + i;
        double side;
        if (dj == 0)
          side = jc > 0 ? c[(jc - 1) * 2 * nxc + i] : south_self * c[i] + south_wrap * c[last];
        else
          side =
              jc < nyc - 1 ? c[(jc + 1) * 2 * nxc + i] : north_self * c[last] + north_wrap * c[i];
        f[(2 * jc + dj) * 2 * nxc + i] = 0.75 * c[jc * 2 * nxc + i] + 0.25 * side;
      }
}

// A coarse cell's coefficient is the mean of its 2x2 fine cells.
DPGEN_KERNEL void mg_average_2x2(DPGEN_IN const double* f, DPGEN_OUT double* c, int nxc, int nyc) {
  for (int jc = 0; jc < nyc; ++jc)
    for (int ic = 0; ic < nxc; ++ic) {
      const int sw = 2 * jc * 2 * nxc + 2 * ic; // south-west fine cell
      c[jc * nxc + ic] = 0.25 * (f[sw] + f[sw + 1] + f[sw + 2 * nxc] + f[sw + 2 * nxc + 1]);
    }
}
