// adversary: work array read beyond what was written (f[n-1] never written)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a10_flux_read_beyond(DPGEN_IN const double* q, DPGEN_OUT double* f,
                                       DPGEN_OUT double* qn, int n) {
  for (int i = 0; i < n - 1; ++i) f[i] = q[i + 1] * q[i];
  for (int i = 0; i < n; ++i) qn[i] = q[i] - (f[i] - 2.0 * f[i]);
}
