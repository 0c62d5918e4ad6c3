// adversary: a later-writer pair fills the work array from the old values, then the update
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_lastwriter_work(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int j = 0; j < n; ++j) {
    w[j] = u[j] * u[j];
    w[j + 1] = 2.0 * u[j];
  }
  for (int i = 0; i < n; ++i) u[i] = u[i] + w[i + 1] - w[i];
}
