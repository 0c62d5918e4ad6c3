#include "dpgen/annotate.hpp"
DPGEN_KERNEL void localarr_varidx(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double v[2] = {a[i], a[i] * a[i]};
    out[i] = v[i % 2];
  }
}
