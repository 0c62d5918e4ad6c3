// r3: a using alias of std::size_t for sizes, mirrored store and read
#include "dpgen/annotate.hpp"
#include <cstddef>
using index_type = std::size_t;
DPGEN_KERNEL void r3_using_mirror_store(DPGEN_IN const double* a, DPGEN_OUT double* o, index_type n) {
  for (index_type i = 0; i < n; ++i) o[n - 1 - i] = a[i] * a[n - 1 - i] + a[i];
}
