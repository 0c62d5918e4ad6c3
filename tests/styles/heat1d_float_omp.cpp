// Single-precision heat step with a nonlinear (temperature-dependent)
// diffusivity, OpenMP parallel for on the loop.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat1d_float_omp(DPGEN_IN const float* t, DPGEN_OUT float* t_new, int n,
                                   float r) {
#pragma omp parallel for
  for (int i = 1; i < n - 1; ++i) {
    float kap = 1.0f + 0.1f * t[i] * t[i];
    t_new[i] = t[i] + r * kap * (t[i - 1] - 2.0f * t[i] + t[i + 1]);
  }
}
