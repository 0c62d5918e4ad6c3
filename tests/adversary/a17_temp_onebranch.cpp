// adversary: function-scope temp assigned in one branch only, then read
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a17_temp_onebranch(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double t;
  for (int i = 0; i < n; ++i) {
    if (a[i] > 0) t = a[i];
    o[i] = t * t;
  }
}
