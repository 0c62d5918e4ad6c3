// adversary: a global max of per-row maxima (a reduction over a reduction)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_max_of_rowmax(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double gm = -1e3;
  for (int j = 0; j < ny; ++j) {
    double m = -1e3;
    for (int i = 0; i < nx; ++i) m = fmax(m, a[j * nx + i]);
    gm = fmax(gm, 2.0 * m);
  }
  out[0] = gm;
}
