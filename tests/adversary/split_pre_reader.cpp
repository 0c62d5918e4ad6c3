// A straight-line store before a loop, and one after it that reads the work
// array the loop wrote: the second runs after the loop (issue 9, nest order).
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void split_pre_reader(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  o[1] = a[0] * a[0];
  for (int i = 0; i < n; ++i)
    w[i] = 2.0 * a[i] * a[i];
  o[0] = w[0] * w[n - 1];
}
