// adversary: one arm writes w then reads it as a work array, the other writes w only
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_arm_output_as_work(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                           DPGEN_OUT double* u, int n, int flag) {
  if (flag == 1) {
    for (int i = 0; i < n; ++i) w[i] = a[i] * a[i];
    for (int i = 1; i < n; ++i) u[i] = w[i] * w[i - 1];
    if (n > 0) u[0] = w[0];
  } else {
    for (int i = 0; i < n; ++i) w[i] = 2.0 * a[i];
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
  }
}
