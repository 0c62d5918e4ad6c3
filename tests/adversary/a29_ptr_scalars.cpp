// adversary: scalars by pointer (int lo/hi, double dt)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a29_ptr_scalars(DPGEN_IN const double* u, DPGEN_OUT double* o, const int* xmin, const int* xmax, const double* dt) {
  int x_min = *xmin, x_max = *xmax;
  for (int i = x_min; i <= x_max; ++i) o[i] = u[i] - *dt * (u[i + 1] * u[i + 1] - u[i - 1]);
}
