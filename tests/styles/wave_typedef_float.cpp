// 1D wave step in single precision selected by `typedef float FLOAT;`,
// C89 counter.
#include "dpgen/annotate.hpp"

typedef float FLOAT;

DPGEN_KERNEL void wave_typedef_float(DPGEN_IN const FLOAT* u, DPGEN_IN const FLOAT* u_prev,
                                     DPGEN_OUT FLOAT* u_next, int n, FLOAT c2)
{
  int i;
  for (i = 1; i < n - 1; ++i)
    u_next[i] = 2.0f * u[i] - u_prev[i] + c2 * (u[i + 1] - 2.0f * u[i] + u[i - 1]);
}
