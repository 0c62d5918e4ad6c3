#include "dpgen/annotate.hpp"
#include <cmath>
DPGEN_KERNEL void semilag(DPGEN_IN const double* q, DPGEN_IN const double* v, DPGEN_OUT double* out, int n, double dt) {
  for (int i = 0; i < n; ++i) {
    double x = i - dt * v[i];
    int i0 = (int)std::floor(x);
    double f = x - i0;
    int l = i0 < 0 ? i0 + n : i0;
    int r = l + 1 == n ? 0 : l + 1;
    out[i] = (1.0 - f) * q[l] + f * q[r];
  }
}
