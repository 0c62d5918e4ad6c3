// adversary: exclusive arms: one a triangular nest, the other a parity nest, same output
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_elseif_accum_rows(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) e[i * n + j] = a[i] * a[j];
  } else if (flag == 1) {
    for (int i = 0; i < n; ++i)
      for (int j = i % 2; j < n; j += 2) e[i * n + j] = a[j] * a[j] * a[i];
  }
}
