// Face flux stored to an output, then read back in the same iteration to
// form the cell update (both are outputs).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void flux_readback(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                                DPGEN_OUT double* flux, DPGEN_OUT double* dq, int n,
                                double inv_dx) {
  for (int i = 1; i < n; ++i) {
    flux[i] = vel[i] * 0.5 * (q[i] + q[i - 1]);
    dq[i] = -flux[i] * flux[i] * inv_dx;
  }
}
