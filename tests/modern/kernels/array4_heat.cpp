// corpus: form=array4 expect=accept
// AMReX heat equation (HeatEquation tutorial, CPU loop style): one box's
// explicit update with loops from lbound/ubound and Array4 views by const&;
// phi_old carries one ghost cell around bx.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void heat_update(Box const& bx, DPGEN_IN Array4<Real const> const& phi_old,
                              DPGEN_OUT Array4<Real> const& phi_new, Real dt, Real dxinv,
                              Real dyinv, Real dzinv) {
  const auto lo = lbound(bx);
  const auto hi = ubound(bx);
  const Real cx = dt * dxinv * dxinv, cy = dt * dyinv * dyinv, cz = dt * dzinv * dzinv;
  for (int k = lo.z; k <= hi.z; ++k) {
    for (int j = lo.y; j <= hi.y; ++j) {
      AMREX_PRAGMA_SIMD
      for (int i = lo.x; i <= hi.x; ++i) {
        phi_new(i, j, k) =
            phi_old(i, j, k) +
            cx * (phi_old(i + 1, j, k) - 2.0 * phi_old(i, j, k) + phi_old(i - 1, j, k)) +
            cy * (phi_old(i, j + 1, k) - 2.0 * phi_old(i, j, k) + phi_old(i, j - 1, k)) +
            cz * (phi_old(i, j, k + 1) - 2.0 * phi_old(i, j, k) + phi_old(i, j, k - 1));
      }
    }
  }
}
