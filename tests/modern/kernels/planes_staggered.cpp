// corpus: form=planes expect=accept
// Staggered (MAC) velocity components kept as planes of one array, each
// plane (ny+1) x (nx+1) nodes: u = plane 0, v = plane 1; divergence at cell
// centers, and the gradient of a pressure back onto the faces of plane d.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void mac_divergence(DPGEN_IN const double* vel, DPGEN_OUT double* div, int nx, int ny,
                                 double inv_h) {
  const int plane = (ny + 1) * (nx + 1);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      div[j * nx + i] =
          inv_h * (vel[0 * plane + j * (nx + 1) + i + 1] - vel[0 * plane + j * (nx + 1) + i] +
                   vel[1 * plane + (j + 1) * (nx + 1) + i] - vel[1 * plane + j * (nx + 1) + i]);
}

DPGEN_KERNEL void mac_gradient(DPGEN_IN const double* p, DPGEN_OUT double* grad, int nx, int ny,
                               double inv_h) {
  for (int d = 0; d < 2; ++d)
    for (int j = d; j < ny; ++j)
      for (int i = 1 - d; i < nx; ++i) {
        const int c = j * nx + i;
        const int nb = d == 0 ? c - 1 : c - nx;
        grad[d * (ny + 1) * (nx + 1) + j * (nx + 1) + i] = inv_h * (p[c] - p[nb]);
      }
}
