// r3: periodic neighbours set by conditionals on int locals
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_periodic_if(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int ip = i + 1;
    if (ip == n) ip = 0;
    int im = i - 1;
    if (im < 0) im = n - 1;
    o[i] = a[ip] * a[im] - 2.0 * a[i];
  }
}
