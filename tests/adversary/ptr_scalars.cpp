#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ptr_scalars(DPGEN_IN const double* a, DPGEN_OUT double* out, const int* xmin, const int* xmax, const double* dt) {
  int x_min = *xmin;
  int x_max = *xmax;
  double d = *dt;
  for (int i = x_min; i <= x_max; ++i)
    out[i - x_min] = d * a[i + 1] * a[i - 1] + a[i];
}
