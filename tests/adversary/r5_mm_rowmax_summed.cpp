// adversary: per-row max fed into a sum over rows
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_rowmax_summed(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double tot = 0.0;
  for (int j = 0; j < ny; ++j) {
    double m = -1e3;
    for (int i = 0; i < nx; ++i) m = fmax(m, a[j * nx + i]);
    tot += m * m;
  }
  out[0] = tot;
}
