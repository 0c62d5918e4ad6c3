// corpus: form=deep expect=accept
// A 4-deep nest: components l outermost, then k, j, i, over a flat array of
// ncomp planes (((l*nz + k)*ny + j)*nx + i); interior 7-point stencil.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void component_laplacian(DPGEN_IN const double* q, DPGEN_OUT double* lq, int ncomp,
                                      int nz, int ny, int nx, double c) {
  const int plane = nx * ny;
  for (int l = 0; l < ncomp; ++l)
    for (int k = 1; k < nz - 1; ++k)
      for (int j = 1; j < ny - 1; ++j)
        for (int i = 1; i < nx - 1; ++i) {
          const int idx = ((l * nz + k) * ny + j) * nx + i;
          lq[idx] = c * (q[idx - 1] + q[idx + 1] + q[idx - nx] + q[idx + nx] + q[idx - plane] +
                         q[idx + plane] - 6.0 * q[idx]);
        }
}
