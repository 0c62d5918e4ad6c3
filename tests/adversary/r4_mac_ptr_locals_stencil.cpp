// adversary: IDX with locals from pointers, 5-point stencil
#include "dpgen/annotate.hpp"
#define IDX(i, j) ((i) - (x_min - 1) + ((j) - (x_min - 1)) * (x_max - x_min + 3))

DPGEN_KERNEL void r4_mac_ptr_locals_stencil(const int* xmin, const int* xmax, DPGEN_IN const double* u,
                                            DPGEN_OUT double* v) {
  int x_min = *xmin, x_max = *xmax;
  for (int k = x_min; k <= x_max; k++)
    for (int j = x_min; j <= x_max; j++)
      v[IDX(j, k)] = u[IDX(j - 1, k)] * u[IDX(j + 1, k)] + u[IDX(j, k - 1)] - u[IDX(j, k + 1)] * u[IDX(j, k)];
}
