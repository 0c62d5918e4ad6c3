// adversary: function-scope temp read before it is assigned in the iteration
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a18_temp_readfirst(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double t = 0;
  for (int i = 0; i < n; ++i) {
    o[i] = t * a[i];
    t = a[i];
  }
}
