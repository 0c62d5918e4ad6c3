// adversary: store at std::max(i-1,0): element 0 written twice
#include "dpgen/annotate.hpp"

#include <algorithm>
DPGEN_KERNEL void a21_store_max_index(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[std::max(i - 1, 0)] = a[i] * a[i];
}
