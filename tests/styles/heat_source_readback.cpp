// Heat step followed by a reaction term on the updated value: the output cell
// is stored, read back and stored again in the same iteration. Leading guard.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat_source_readback(DPGEN_IN const double* t, DPGEN_IN const double* src,
                                       DPGEN_OUT double* t_new, int n, double r, double dt) {
  if (n < 3)
    return;
  for (int i = 1; i < n - 1; ++i) {
    t_new[i] = t[i] + r * (t[i - 1] - 2.0 * t[i] + t[i + 1]);
    t_new[i] = t_new[i] + dt * src[i] * t_new[i];
  }
}
