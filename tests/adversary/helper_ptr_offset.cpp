#include "dpgen/annotate.hpp"
static double lap(const double* u, int i) { return u[i - 1] - 2.0 * u[i] + u[i + 1]; }
static double lap2(const double* u, int i) { return lap(u + 1, i - 1) * u[i]; }
DPGEN_KERNEL void helper_ptr_offset(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = lap2(a, i);
}
