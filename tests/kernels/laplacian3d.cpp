// 7-point Laplacian on an nx*ny*nz grid (x fastest); boundary cells are zero.
// The flat index is a long: nx*ny*nz passes 2^31 on large grids.
#include "test_kernels.hpp"

DPGEN_KERNEL void laplacian3d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny,
                              int nz, double h) {
  const long plane = static_cast<long>(nx) * ny;
  for (int l = 0; l < nz; ++l)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const long k = (static_cast<long>(l) * ny + j) * nx + i;
        if (i == 0 || i == nx - 1 || j == 0 || j == ny - 1 || l == 0 || l == nz - 1) {
          out[k] = 0.0;
          continue;
        }
        out[k] = (a[k - 1] + a[k + 1] + a[k - nx] + a[k + nx] + a[k - plane] + a[k + plane] -
                  6.0 * a[k]) /
                 (h * h);
      }
}
