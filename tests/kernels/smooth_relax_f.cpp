// A float kernel: smooth nonlinear relaxation towards neighbours (tanh, exp),
// non-periodic, with the last cell copied.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void smooth_relax_f(DPGEN_IN const float* a, DPGEN_IN const float* b,
                                 DPGEN_OUT float* out, int n, float rate) {
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) {
      out[i] = a[i];
      continue;
    }
    float pull = std::tanh(a[i + 1] - a[i]);
    float damp = std::exp(-b[i] * b[i]);
    out[i] = a[i] + rate * pull * damp;
  }
}
