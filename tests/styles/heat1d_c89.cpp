// Explicit FTCS heat step written C89 style: counter declared at the top of
// the function, post-increment.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat1d_c89(DPGEN_IN const double* u, DPGEN_OUT double* u_new, int n, double r)
{
  int i;
  for (i = 1; i < n - 1; i++) {
    u_new[i] = u[i] + r * (u[i - 1] - 2.0 * u[i] + u[i + 1]);
  }
}
