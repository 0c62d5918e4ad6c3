// adversary: size_t and unsigned counters, n > i
#include "dpgen/annotate.hpp"

#include <cstddef>
DPGEN_KERNEL void a14_unsigned(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* p, std::size_t n) {
  for (std::size_t i = 1; i + 1 < n; ++i) o[i] = a[i + 1] * a[i - 1];
  for (unsigned i = 0; n > i; i++) p[i] = a[i] * a[i];
}
