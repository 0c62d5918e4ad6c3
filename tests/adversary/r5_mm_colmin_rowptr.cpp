// adversary: colmin[i] = a[0][i]; for j from 0: if (a[j][i] < colmin[i]) colmin[i] = a[j][i]; (double**)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_colmin_rowptr(DPGEN_IN double** a, DPGEN_OUT double* colmin, int nx, int ny) {
  for (int i = 0; i < nx; ++i) {
    colmin[i] = a[0][i];
    for (int j = 0; j < ny; ++j)
      if (a[j][i] < colmin[i]) colmin[i] = a[j][i];
  }
}
