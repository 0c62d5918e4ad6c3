// adversary: the update loop is a later-writer pair over u (reads only a work array)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_lastwriter_update(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[i] * u[i + 1];
  for (int j = 0; j < n; ++j) {
    u[j] = w[j];
    u[j + 1] = 2.0 * w[j];
  }
}
