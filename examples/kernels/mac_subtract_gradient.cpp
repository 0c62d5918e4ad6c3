// u - grad p on the periodic MAC grid: each face takes the difference of the
// two cells it separates.
#include "example_kernels.hpp"

DPGEN_KERNEL void mac_subtract_gradient(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                        DPGEN_IN const double* p, DPGEN_OUT double* u_out,
                                        DPGEN_OUT double* v_out, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      const int iw = i == 0 ? nx - 1 : i - 1;
      const int js = j == 0 ? ny - 1 : j - 1;
      u_out[k] = u[k] - (p[k] - p[j * nx + iw]) / h;
      v_out[k] = v[k] - (p[k] - p[js * nx + i]) / h;
    }
}
