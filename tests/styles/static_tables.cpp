// Filter weights in a function-local `static const` table and a `static
// constexpr` gain, as C and Fortran-ported codes keep their constants (once
// per program, not per call); a nonlinear use of the filtered value.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void static_tables(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  static const double w[5] = {-0.0625, 0.25, 0.625, 0.25, -0.0625};
  static constexpr double gain = 1.5;
  for (int i = 2; i < n - 2; ++i) {
    double s = 0.0;
    for (int m = 0; m < 5; ++m)
      s += w[m] * a[i - 2 + m];
    out[i] = gain * s * a[i];
  }
}
