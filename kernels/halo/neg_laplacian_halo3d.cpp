// -Laplacian, 7-point, on a padded block given by its padded extents px = nx + 2, py, pz. The
// loops run over the whole padded box and skip the halo cells (loops over the full row lengths
// let dpgen prove that every output cell is written once). Flat indices in 64 bits: they
// multiply three sizes.
#include "halo_kernels.hpp"

DPGEN_KERNEL void neg_laplacian_halo3d(DPGEN_IN const double* p, DPGEN_OUT double* out, int px,
                                       int py, int pz, double h) {
  const long plane = static_cast<long>(px) * py;
  for (int l = 0; l < pz; ++l)
    for (int j = 0; j < py; ++j)
      for (int i = 0; i < px; ++i) {
        if (i == 0 || i == px - 1 || j == 0 || j == py - 1 || l == 0 || l == pz - 1)
          continue; // a halo cell: neither computed nor written
        const long c = (static_cast<long>(l) * py + j) * px + i;
        const double sum =
            p[c + 1] + p[c - 1] + p[c + px] + p[c - px] + p[c + plane] + p[c - plane];
        out[c] = (6.0 * p[c] - sum) / (h * h);
      }
}
