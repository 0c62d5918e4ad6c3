// corpus: form=global expect=accept
// Per-species diffusion coefficients in a global array marked DPGEN_IN (a
// model parameter to calibrate), used in a component loop; a constexpr
// global weight table is a constant.
#include "dpgen/annotate.hpp"

constexpr int NSPEC = 3;
constexpr double lap_w[3] = {1.0, -2.0, 1.0};
DPGEN_IN double g_diff[NSPEC] = {0.1, 0.2, 0.3};

DPGEN_KERNEL void species_rhs(DPGEN_IN const double* y, DPGEN_OUT double* rhs, int n,
                              double inv_h2) {
  for (int s = 0; s < NSPEC; ++s)
    for (int i = 1; i < n - 1; ++i) {
      double l = 0.0;
      for (int m = 0; m < 3; ++m)
        l += lap_w[m] * y[s * n + i - 1 + m];
      rhs[s * n + i] = g_diff[s] * inv_h2 * l;
    }
}
