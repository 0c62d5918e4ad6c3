// out = u + c * (periodic second difference of u): linear in u, so its
// adjoint is the transposed matrix and the dot-product identity is exact.
#include "smooth.hpp"

DPGEN_KERNEL void smooth(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double c) {
  for (int i = 0; i < n; ++i) {
    const int ip = (i == n - 1) ? 0 : i + 1;
    const int im = (i == 0) ? n - 1 : i - 1;
    out[i] = u[i] + c * (u[ip] - 2.0 * u[i] + u[im]);
  }
}
