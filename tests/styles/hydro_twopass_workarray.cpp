// Conservative update in two passes, as hydro codes do: face fluxes
// (Rusanov) into a work array, then the flux difference per cell.
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

DPGEN_KERNEL void hydro_twopass_workarray(DPGEN_IN const double* q, DPGEN_OUT double* flux,
                                          DPGEN_OUT double* q_new, int n, double dt_dx) {
  // face i sits between cells i-1 and i
  for (int i = 1; i < n; ++i) {
    const double ql = q[i - 1], qr = q[i];
    const double fl = 0.5 * ql * ql, fr = 0.5 * qr * qr;
    const double smax = std::max(std::fabs(ql), std::fabs(qr));
    flux[i] = 0.5 * (fl + fr) - 0.5 * smax * (qr - ql);
  }
  for (int i = 1; i < n - 1; ++i)
    q_new[i] = q[i] - dt_dx * (flux[i + 1] - flux[i]);
}
