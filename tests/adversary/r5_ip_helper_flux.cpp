// adversary: fluxes through a limiter helper, then the update in place
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline double minmod(double a, double b) { return a * b <= 0.0 ? 0.0 : (std::fabs(a) < std::fabs(b) ? a : b); }

DPGEN_KERNEL void r5_ip_helper_flux(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 1; i < n - 1; ++i) f[i] = u[i] + 0.5 * minmod(u[i] - u[i - 1], u[i + 1] - u[i]);
  for (int i = 2; i < n - 1; ++i) u[i] -= 0.4 * (f[i] - f[i - 1]);
}
