// adversary: null adjoint for one input leaves the other's adjoint identical
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a42_null_adj(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) w[i] = a[i] * b[i];
  for (int i = 1; i < n - 1; ++i) o[i] = w[i - 1] * b[i + 1] + a[i] * w[i + 1];
}
