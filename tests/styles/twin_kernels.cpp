// Two identical kernels in one file (a smoother applied along x and along y
// of a transposed buffer): the generated code must not depend on which one
// is processed first.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void smooth_sq_x(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double s) {
  for (int i = 1; i < n - 1; ++i) {
    double g = a[i + 1] - a[i - 1];
    out[i] = a[i] + s * std::sqrt(1.0 + g * g) * (a[i + 1] - 2.0 * a[i] + a[i - 1]);
  }
}

DPGEN_KERNEL void smooth_sq_y(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double s) {
  for (int i = 1; i < n - 1; ++i) {
    double g = a[i + 1] - a[i - 1];
    out[i] = a[i] + s * std::sqrt(1.0 + g * g) * (a[i + 1] - 2.0 * a[i] + a[i - 1]);
  }
}
