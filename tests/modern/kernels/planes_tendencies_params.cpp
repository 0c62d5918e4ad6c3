// corpus: form=planes expect=accept
// miniWeather's compute_tendencies_x again, with the sizes and background
// passed as parameters instead of globals, so that only the plane offsets
// (ll*(nz+1)*(nx+1) + k*(nx+1) + i) and the local stencil buffers are tested.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void tendencies_x(DPGEN_IN const double* state, DPGEN_OUT double* flux,
                               DPGEN_OUT double* tend, const double* hy_dens_cell,
                               const double* hy_dens_theta_cell, int nx, int nz, double dx,
                               double dt) {
  const int NUM_VARS = 4, hs = 2;
  const double C0 = 27.5629410929725921310572974482;
  const double gamm = 1.40027894002789400278940027894;
  const double hv_coef = -0.05 * dx / (16 * dt);
  double stencil[4], d3_vals[4], vals[4];
  for (int k = 0; k < nz; k++) {
    for (int i = 0; i < nx + 1; i++) {
      for (int ll = 0; ll < NUM_VARS; ll++) {
        for (int s = 0; s < 4; s++)
          stencil[s] = state[ll * (nz + 2 * hs) * (nx + 2 * hs) + (k + hs) * (nx + 2 * hs) + i + s];
        vals[ll] = -stencil[0] / 12 + 7 * stencil[1] / 12 + 7 * stencil[2] / 12 - stencil[3] / 12;
        d3_vals[ll] = -stencil[0] + 3 * stencil[1] - 3 * stencil[2] + stencil[3];
      }
      const double r = vals[0] + hy_dens_cell[k + hs];
      const double u = vals[1] / r;
      const double w = vals[2] / r;
      const double t = (vals[3] + hy_dens_theta_cell[k + hs]) / r;
      const double p = C0 * std::pow(r * t, gamm);
      flux[0 * (nz + 1) * (nx + 1) + k * (nx + 1) + i] = r * u - hv_coef * d3_vals[0];
      flux[1 * (nz + 1) * (nx + 1) + k * (nx + 1) + i] = r * u * u + p - hv_coef * d3_vals[1];
      flux[2 * (nz + 1) * (nx + 1) + k * (nx + 1) + i] = r * u * w - hv_coef * d3_vals[2];
      flux[3 * (nz + 1) * (nx + 1) + k * (nx + 1) + i] = r * u * t - hv_coef * d3_vals[3];
    }
  }
  for (int ll = 0; ll < NUM_VARS; ll++)
    for (int k = 0; k < nz; k++)
      for (int i = 0; i < nx; i++)
        tend[ll * nz * nx + k * nx + i] = -(flux[ll * (nz + 1) * (nx + 1) + k * (nx + 1) + i + 1] -
                                            flux[ll * (nz + 1) * (nx + 1) + k * (nx + 1) + i]) /
                                          dx;
}
