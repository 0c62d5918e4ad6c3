// r3: float kernel, integer division in a float value and a long local from size_t
#include "dpgen/annotate.hpp"
#include <cstddef>
DPGEN_KERNEL void r3_float_int_div(DPGEN_IN const float* a, DPGEN_OUT float* o, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    long h = (long)(n - i) / 2;
    o[i] = a[i] * (float)(i / 2) + 0.5f * h * a[n - 1 - i];
  }
}
