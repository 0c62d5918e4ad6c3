// adversary: work array: fluxes then update
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a09_flux_update(DPGEN_IN const double* q, DPGEN_OUT double* f,
                                  DPGEN_OUT double* qn, int n) {
  for (int i = 0; i < n - 1; ++i) f[i] = 0.5 * (q[i + 1] * q[i + 1] + q[i] * q[i]);
  for (int i = 1; i < n - 1; ++i) qn[i] = q[i] - 0.3 * (f[i] - f[i - 1]) * f[i];
}
