// corpus: form=template expect=accept
// A template kernel on Array4<Real const> / Array4<Real> (AMReX codes
// template kernels on the real type for mixed precision), explicitly
// instantiated for double. Nonlinear: a flux-limited smoothing.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

#include <cmath>

template <typename T>
DPGEN_KERNEL void smooth_box(amrex::Box const& bx, DPGEN_IN amrex::Array4<T const> const& a,
                             DPGEN_OUT amrex::Array4<T> const& b, T w) {
  const auto lo = amrex::lbound(bx);
  const auto hi = amrex::ubound(bx);
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) {
        const T d = a(i + 1, j, k) - 2 * a(i, j, k) + a(i - 1, j, k);
        b(i, j, k) = a(i, j, k) + w * d / (T(1) + d * d);
      }
}

template void smooth_box<double>(amrex::Box const&, amrex::Array4<double const> const&,
                                 amrex::Array4<double> const&, double);
