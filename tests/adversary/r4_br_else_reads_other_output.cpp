// adversary: else arm's second output reads the first output (work array) written by both arms
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_else_reads_other_output(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                                DPGEN_OUT double* v, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) w[i] = a[i] + 1.0;
    for (int i = 0; i < n; ++i) v[i] = a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) w[i] = a[i] * a[i];
    for (int i = 0; i + 1 < n; ++i) v[i] = w[i] * w[i + 1];
    if (n > 0) v[n - 1] = w[n - 1];
  }
}
