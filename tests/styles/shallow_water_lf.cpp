// Lax-Friedrichs step for the 1D shallow-water equations (h, hu). C89
// counter, temporaries at function scope listed in an OpenMP private clause
// and assigned before use in every iteration.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void shallow_water_lf(DPGEN_IN const double* h, DPGEN_IN const double* hu,
                                   DPGEN_OUT double* h_new, DPGEN_OUT double* hu_new, int n,
                                   double dt_dx, double g)
{
  int i;
  double hl, hr, ul, ur, fl_hu, fr_hu;
#pragma omp parallel for private(hl, hr, ul, ur, fl_hu, fr_hu)
  for (i = 1; i < n - 1; ++i) {
    hl = h[i - 1];
    hr = h[i + 1];
    ul = hu[i - 1] / hl;
    ur = hu[i + 1] / hr;
    fl_hu = hu[i - 1] * ul + 0.5 * g * hl * hl;
    fr_hu = hu[i + 1] * ur + 0.5 * g * hr * hr;
    h_new[i] = 0.5 * (hl + hr) - 0.5 * dt_dx * (hu[i + 1] - hu[i - 1]);
    hu_new[i] = 0.5 * (hu[i - 1] + hu[i + 1]) - 0.5 * dt_dx * (fr_hu - fl_hu);
  }
}
