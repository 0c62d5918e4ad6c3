// Two sequential loops over the same counter name where the second reads an
// input at a shifted index and has a shifted upper bound: smoothing into one
// output, a one-sided difference into another.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void smooth_then_scale(DPGEN_IN const double* a, DPGEN_IN const double* s,
                                    DPGEN_OUT double* sm, DPGEN_OUT double* d, int n) {
  for (int i = 1; i < n - 1; ++i)
    sm[i] = 0.25 * a[i - 1] + 0.5 * a[i] + 0.25 * a[i + 1];
  for (int i = 0; i < n - 1; ++i)
    d[i] = s[i] * (a[i + 1] - a[i]);
}
