// adversary: branch on a double parameter
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_double_param(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, double dt) {
  if (dt > 0.5) {
    for (int i = 0; i < n; ++i) u[i] = dt * a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) u[i] = a[i] - dt;
  }
}
