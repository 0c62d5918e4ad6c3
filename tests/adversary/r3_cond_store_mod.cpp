// r3: store on i % 2 branch, both branches write
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_cond_store_mod(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0) o[i] = a[i] * a[i];
    else o[i] = -a[n - 1 - i];
  }
}
