// Heat step with variable conductivity: both end cells are stored before the
// interior loop and depend on the inputs; no guard, so for n == 1 both end
// stores hit cell 0 (the second wins).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat1d_ends(DPGEN_IN const double* t, DPGEN_IN const double* k,
                              DPGEN_OUT double* t_new, int n, double r) {
  t_new[0] = 0.5 * t[0] + k[0];
  t_new[n - 1] = 2.0 * t[n - 1] * k[n - 1];
  for (int i = 1; i < n - 1; ++i)
    t_new[i] = t[i] + r * k[i] * (t[i + 1] - 2.0 * t[i] + t[i - 1]);
}
