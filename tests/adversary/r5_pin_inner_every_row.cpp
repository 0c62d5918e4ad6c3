// adversary: if (i == 0) out[0] = ... inside a row loop: ny iterations store out[0]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_inner_every_row(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (i == 0) out[0] = a[j * nx + i] * a[j * nx + i];
}
