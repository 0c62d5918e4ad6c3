// r3: two inputs, two outputs, one stored mirrored (size_t n)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_two_out_mirror(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* p, DPGEN_OUT double* q, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = a[i] * b[n - 1 - i];
    q[n - 1 - i] = a[i] + b[i] * b[i];
  }
}
