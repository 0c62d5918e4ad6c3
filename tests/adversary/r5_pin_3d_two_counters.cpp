// adversary: if (i == k) in a 3D nest storing e[j]: nz iterations per element
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_3d_two_counters(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (i == k) e[j] = a[(k * n + j) * n + i] * a[(k * n + j) * n + i];
}
