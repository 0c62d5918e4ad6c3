// r3: an int local from a double expression of the size, k = (int)(0.5 * n), used as a read index
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_int_from_double_idx(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  const int k = (int)(0.5 * n);
  for (int i = 0; i < n; ++i) o[i] = a[i] * a[k] + a[(int)(0.25 * i)];
}
