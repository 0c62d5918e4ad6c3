// corpus: form=array4 expect=accept
// AMReX-style conservative update of ncomp components from face fluxes
// (4-deep nest, n outermost), divided by a constant cell-volume Array4 that
// is not differentiated.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void flux_divergence(Box const& bx, int ncomp, DPGEN_IN Array4<Real const> const& fx,
                                  DPGEN_IN Array4<Real const> const& fy,
                                  DPGEN_IN Array4<Real const> const& fz,
                                  Array4<Real const> const& vol, DPGEN_OUT Array4<Real> const& dsdt,
                                  Real dt) {
  const auto lo = lbound(bx);
  const auto hi = ubound(bx);
  for (int n = 0; n < ncomp; ++n)
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j) {
        AMREX_PRAGMA_SIMD
        for (int i = lo.x; i <= hi.x; ++i) {
          dsdt(i, j, k, n) =
              dt / vol(i, j, k) *
              ((fx(i, j, k, n) - fx(i + 1, j, k, n)) + (fy(i, j, k, n) - fy(i, j + 1, k, n)) +
               (fz(i, j, k, n) - fz(i, j, k + 1, n)));
        }
      }
}
