// adversary: start (j + k) % 3, step 3 (3D)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_ij_mod3(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = (j + k) % 3; i < n; i += 3)
        e[(k * n + j) * n + i] = a[(k * n + j) * n + i] * a[i];
}
