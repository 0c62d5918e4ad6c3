// adversary: for j: K[j] = f; for j: K[j + 1] = g; (a later loop overwrites: a run-time check throws for n >= 2)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_two_loops_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) K[j] = a[j] * a[j];
  for (int j = 0; j < n; ++j) K[j + 1] = std::sin(a[j]);
}
