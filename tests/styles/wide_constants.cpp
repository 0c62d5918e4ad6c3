// Constants that the IR once changed: an unsigned literal past 2^31 (read
// as a negative number, so `i < 3000000000u` was false), the literal -0.0
// (printed as 0.0, flipping std::copysign), and std::fmax / std::fmin
// (printed as a max that returns a NaN first argument, where fmax returns the
// other one). Found by a helper's corpus (session 19).
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void big_unsigned_literal(DPGEN_IN const double* u, DPGEN_OUT double* v, unsigned n) {
  for (unsigned i = 0; i < n; ++i)
    v[i] = u[i] * u[i] * (i < 3000000000u ? 1.0 : 2.0) + 3000000000u * 1e-9 +
           static_cast<double>(0x80000000) * 1e-9;
}

DPGEN_KERNEL void copysign_neg_zero(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    v[i] = std::copysign(u[i] * u[i] + 0.5, -0.0) * u[i];
}

DPGEN_KERNEL void fmax_nan_clip(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    v[i] = std::fmax(std::sqrt(u[i]), 0.0) + std::fmin(u[i], std::sqrt(u[i] + 0.5)) * u[i];
}
