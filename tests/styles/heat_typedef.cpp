// Heat step with the precision chosen by a user typedef in the signature.
#include "dpgen/annotate.hpp"

typedef double FLOAT;

DPGEN_KERNEL void heat_typedef(DPGEN_IN const FLOAT* u, DPGEN_IN const FLOAT* alpha,
                               DPGEN_OUT FLOAT* u_new, int n, FLOAT r) {
  for (int i = 1; i < n - 1; ++i)
    u_new[i] = u[i] + r * alpha[i] * (u[i - 1] - 2.0 * u[i] + u[i + 1]);
}
