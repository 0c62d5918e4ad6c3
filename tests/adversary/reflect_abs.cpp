#include "dpgen/annotate.hpp"
#include <cstdlib>
DPGEN_KERNEL void reflect_abs(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[std::abs(i - 1)] * a[i];
}
