// The math functions added as rows of the operation table (tool/lib/ops.cpp):
// atan2, hypot, erf, cbrt, copysign, fma, log1p, expm1, each once, in a double
// kernel with std:: names and a float one with the C names (atan2f, ...).
// Inputs: a, c in [0.5, 2], b in [-1, 1].
#include "test_kernels.hpp"

#include <cmath>
#include <math.h>

DPGEN_KERNEL void special_math(DPGEN_IN const double* a, DPGEN_IN const double* b,
                               DPGEN_IN const double* c, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = std::atan2(b[i], a[i]) + std::hypot(a[i], b[i]);
    s += std::erf(b[i]) * std::cbrt(a[i] + c[i]);
    s += std::copysign(a[i] * c[i], b[i]);
    s += std::fma(a[i], b[i], c[i]) * std::log1p(a[i] * c[i]) + std::expm1(b[i] * c[i]);
    out[i] = s;
  }
}

DPGEN_KERNEL void special_math_f(DPGEN_IN const float* a, DPGEN_IN const float* b,
                                 DPGEN_IN const float* c, DPGEN_OUT float* out, int n) {
  for (int i = 0; i < n; ++i) {
    float s = atan2f(a[i], b[i] + 2.0f) - hypotf(c[i], b[i]);
    s += erff(0.5f * b[i]) + cbrtf(c[i]) * copysignf(b[i], -1.0f);
    out[i] = fmaf(s, a[i], c[i]) + log1pf(c[i]) * expm1f(0.5f * a[i]);
  }
}
