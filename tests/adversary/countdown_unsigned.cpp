#include "dpgen/annotate.hpp"
DPGEN_KERNEL void countdown_unsigned(DPGEN_IN const double* a, DPGEN_OUT double* out, unsigned n) {
  for (unsigned i = n; i-- > 0;)
    out[i] = a[i] * a[n - 1 - i];
}
