// adversary: strided i += 3 from parameter start s, and i += 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a15_stride_param(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* c, int n, int s) {
  for (int i = s; i < n; i += 3) o[i] = a[i] * a[i] + a[i - s];
  for (int i = 0; i + 1 < n; i += 2) c[i / 2] = a[i] * a[i + 1];
}
