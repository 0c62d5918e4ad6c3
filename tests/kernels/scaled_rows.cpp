// Reads at indices that drop a loop counter: a per-column coefficient c[i]
// (summed over rows in the adjoint), a scalar nu[0] (summed over all cells),
// and a constant (non-differentiable) mask.
#include "test_kernels.hpp"

DPGEN_KERNEL void scaled_rows(DPGEN_IN const double* a, DPGEN_IN const double* c,
                              DPGEN_IN const double* nu, const double* mask, DPGEN_OUT double* out,
                              int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      out[k] = mask[k] * c[i] * a[k] * nu[0] + a[k] * a[k];
    }
}
