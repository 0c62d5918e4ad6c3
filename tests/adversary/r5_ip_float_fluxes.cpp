// adversary: float in-place update with fluxes
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_float_fluxes(DPGEN_INOUT float* rho, DPGEN_OUT float* flux, int n) {
  for (int i = 1; i < n; ++i) flux[i] = 0.5f * (rho[i] * rho[i] - rho[i - 1]);
  for (int i = 1; i < n - 1; ++i) rho[i] -= 0.3f * (flux[i + 1] - flux[i]);
}
