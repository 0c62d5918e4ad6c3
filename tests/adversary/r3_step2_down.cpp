// r3: long long counter counting down by 2 (i -= 2), mirror read
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_step2_down(DPGEN_IN const double* a, DPGEN_OUT double* o, long long n) {
  for (long long i = n - 1; i >= 0; i -= 2) o[i] = a[i] * a[n - 1 - i];
}
