// adversary: leading dimension ld separate from nx: correct when ld >= nx, must throw when ld < nx
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a23_ld_param(DPGEN_IN const double* a, DPGEN_OUT double* o, int nx, int ny, int ld) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      o[j * ld + i] = a[j * ld + i] * a[j * ld + i];
}
