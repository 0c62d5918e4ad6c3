// Nonlinear artificial viscosity: the five-point neighbourhood is copied into
// a local line buffer, differences into a second small array.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void viscosity_linebuffer(DPGEN_IN const double* q, DPGEN_OUT double* out, int n,
                                       double eps) {
  for (int i = 2; i < n - 2; ++i) {
    double v[5];
    double d[4];
    for (int m = 0; m < 5; ++m)
      v[m] = q[i - 2 + m];
    for (int m = 0; m < 4; ++m)
      d[m] = v[m + 1] - v[m];
    out[i] = v[2] + eps * (d[2] * std::fabs(d[2]) - d[1] * std::fabs(d[1])) -
             0.0625 * eps * (d[3] - 2.0 * d[2] + 2.0 * d[1] - d[0]);
  }
}
