// adversary: loop counters named lo_i, hi_i, in_lo_i, parallel_ok
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_counter_names(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const int lo_i = 1, hi_i = n - 1;
  const bool parallel_ok = true;
  for (int in_lo_i = lo_i; in_lo_i < hi_i; ++in_lo_i)
    out[in_lo_i] = parallel_ok ? u[in_lo_i - 1] * u[in_lo_i + 1] : 0.0;
}
