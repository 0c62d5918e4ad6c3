// corpus: form=planes expect=accept
// miniWeather's compute_tendencies_x (C++ version), as written there: the
// sizes and the hydrostatic background are globals, the state and fluxes are
// NUM_VARS planes in one flat array (ll*(nz+1)*(nx+1) + k*(nx+1) + i), a
// 4-point stencil read into a local buffer, then the flux divergence. The
// prover must separate the planes (offsets products of sizes).
#include "dpgen/annotate.hpp"

#include <cmath>

constexpr int NUM_VARS = 4;
constexpr int ID_DENS = 0, ID_UMOM = 1, ID_WMOM = 2, ID_RHOT = 3;
constexpr int hs = 2, sten_size = 4;
constexpr double C0 = 27.5629410929725921310572974482;
constexpr double gamm = 1.40027894002789400278940027894;
constexpr double hv_beta = 0.05;

int nx, nz; // set once by init()
double dx;
double* hy_dens_cell; // hydrostatic background, nz + 2*hs
double* hy_dens_theta_cell;

DPGEN_KERNEL void compute_tendencies_x(DPGEN_IN double* state, DPGEN_OUT double* flux,
                                       DPGEN_OUT double* tend, double dt) {
  int i, k, ll, s, inds, indt, indf1, indf2;
  double r, u, w, t, p, stencil[4], d3_vals[NUM_VARS], vals[NUM_VARS], hv_coef;
  hv_coef = -hv_beta * dx / (16 * dt);
  for (k = 0; k < nz; k++) {
    for (i = 0; i < nx + 1; i++) {
      for (ll = 0; ll < NUM_VARS; ll++) {
        for (s = 0; s < sten_size; s++) {
          inds = ll * (nz + 2 * hs) * (nx + 2 * hs) + (k + hs) * (nx + 2 * hs) + i + s;
          stencil[s] = state[inds];
        }
        vals[ll] = -stencil[0] / 12 + 7 * stencil[1] / 12 + 7 * stencil[2] / 12 - stencil[3] / 12;
        d3_vals[ll] = -stencil[0] + 3 * stencil[1] - 3 * stencil[2] + stencil[3];
      }
      r = vals[ID_DENS] + hy_dens_cell[k + hs];
      u = vals[ID_UMOM] / r;
      w = vals[ID_WMOM] / r;
      t = (vals[ID_RHOT] + hy_dens_theta_cell[k + hs]) / r;
      p = C0 * pow((r * t), gamm);
      flux[ID_DENS * (nz + 1) * (nx + 1) + k * (nx + 1) + i] = r * u - hv_coef * d3_vals[ID_DENS];
      flux[ID_UMOM * (nz + 1) * (nx + 1) + k * (nx + 1) + i] =
          r * u * u + p - hv_coef * d3_vals[ID_UMOM];
      flux[ID_WMOM * (nz + 1) * (nx + 1) + k * (nx + 1) + i] =
          r * u * w - hv_coef * d3_vals[ID_WMOM];
      flux[ID_RHOT * (nz + 1) * (nx + 1) + k * (nx + 1) + i] =
          r * u * t - hv_coef * d3_vals[ID_RHOT];
    }
  }
  for (ll = 0; ll < NUM_VARS; ll++) {
    for (k = 0; k < nz; k++) {
      for (i = 0; i < nx; i++) {
        indt = ll * nz * nx + k * nx + i;
        indf1 = ll * (nz + 1) * (nx + 1) + k * (nx + 1) + i;
        indf2 = ll * (nz + 1) * (nx + 1) + k * (nx + 1) + i + 1;
        tend[indt] = -(flux[indf2] - flux[indf1]) / dx;
      }
    }
  }
}
