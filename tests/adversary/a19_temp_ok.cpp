// adversary: function-scope temps assigned before use, both branches, and reassigned
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a19_temp_ok(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double t, s;
  for (int i = 0; i < n; ++i) {
    if (a[i] > 0) t = a[i] * a[i]; else t = -a[i];
    s = t * 2.0;
    s = s * t;
    o[i] = s + t;
  }
}
