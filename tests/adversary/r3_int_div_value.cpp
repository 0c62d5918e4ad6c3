// r3: integer division and % in values: (i / 2), (1 / 2) == 0, ((n - i) / 3), (i % 3)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_int_div_value(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i)
    o[i] = a[i] * (i / 2) + a[i] * a[i] * (1 / 2) + (double)((n - i) / 3) * a[n - 1 - i] + (i % 3) * a[i] * a[i];
}
