// A MUSCL-type reconstruction in C++ style: a void helper returns the left
// and right states through references (with a branch in it), another writes
// an output element directly.
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

namespace {
inline void reconstruct(double um, double u0, double up, double& left, double& right) {
  double dl = u0 - um, dr = up - u0;
  double slope;
  if (dl * dr <= 0.0) {
    slope = 0.0;
  } else {
    slope = std::abs(dl) < std::abs(dr) ? dl : dr;
  }
  left = u0 - 0.5 * slope;
  right = u0 + 0.5 * slope;
}

inline void put_flux(double* f, int i, double ul, double ur, double c) {
  f[i] = c > 0.0 ? c * ur : c * ul;
}
} // namespace

DPGEN_KERNEL void limiter_refs(DPGEN_IN const double* u, DPGEN_OUT double* f, int n, double c) {
  for (int i = 1; i < n - 2; ++i) {
    double l0, r0, l1, r1;
    reconstruct(u[i - 1], u[i], u[i + 1], l0, r0);
    reconstruct(u[i], u[i + 1], u[i + 2], l1, r1);
    (void)l0;
    (void)r1;
    put_flux(f, i, l1, r0, c);
  }
}
