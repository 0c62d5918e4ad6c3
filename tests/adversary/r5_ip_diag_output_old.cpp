// adversary: a diagnostic output from the old values (energy), and a pinned first value, then the update
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_diag_output_old(DPGEN_INOUT double* u, DPGEN_OUT double* diag, int n) {
  diag[0] = 0.0;
  for (int i = 0; i < n; ++i) {
    diag[0] += 0.5 * u[i] * u[i];
    if (i == 0) diag[1] = u[0];
  }
  for (int i = 0; i < n; ++i) u[i] = std::sin(u[i]);
}
