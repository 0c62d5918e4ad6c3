// r3: work sum then statement after the loop reading it into another output
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_work_accum_after(DPGEN_IN const double* a, DPGEN_OUT double* s, DPGEN_OUT double* o, long n) {
  s[0] = 0;
  for (long i = 0; i < n; ++i) s[0] += a[n - 1 - i] * a[i];
  o[0] = std::sqrt(1.0 + s[0] * s[0]);
}
