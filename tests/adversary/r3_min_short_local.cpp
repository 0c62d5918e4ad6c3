// r3 minimal: a short local wraps ((short)40000 == -25536); dpgen makes it a std::ptrdiff_t (40000)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_min_short_local(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    short s = (short)(i * 20000);
    o[i] = 1e-4 * s * a[i];
  }
}
