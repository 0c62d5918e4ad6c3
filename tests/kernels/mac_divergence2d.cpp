// Divergence on a staggered (MAC) grid: u lives on the (nx+1)*ny vertical
// faces, v on the nx*(ny+1) horizontal faces, div in the nx*ny cells.
#include "test_kernels.hpp"

DPGEN_KERNEL void mac_divergence2d(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                   DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int fu = j * (nx + 1) + i; // west face of cell (i, j)
      const int fv = j * nx + i;       // south face
      div[j * nx + i] = (u[fu + 1] - u[fu] + v[fv + nx] - v[fv]) / h;
    }
}
