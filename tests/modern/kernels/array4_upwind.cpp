// corpus: form=array4 expect=accept
// First-order upwind advection of a scalar by face-centered (MAC) velocities,
// AMReX Advection tutorial style (2D in a 3D box: k runs over one plane).
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

#include <algorithm>

using namespace amrex;

DPGEN_KERNEL void advect_upwind(Box const& bx, DPGEN_IN Array4<Real const> const& q,
                                DPGEN_IN Array4<Real const> const& umac,
                                DPGEN_IN Array4<Real const> const& vmac,
                                DPGEN_OUT Array4<Real> const& qnew, Real dtdx, Real dtdy) {
  const Dim3 lo = lbound(bx);
  const Dim3 hi = ubound(bx);
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) {
        // flux through the low and high x faces, upwinded
        const Real fxl = std::max(umac(i, j, k), 0.0) * q(i - 1, j, k) +
                         std::min(umac(i, j, k), 0.0) * q(i, j, k);
        const Real fxh = std::max(umac(i + 1, j, k), 0.0) * q(i, j, k) +
                         std::min(umac(i + 1, j, k), 0.0) * q(i + 1, j, k);
        const Real fyl = std::max(vmac(i, j, k), 0.0) * q(i, j - 1, k) +
                         std::min(vmac(i, j, k), 0.0) * q(i, j, k);
        const Real fyh = std::max(vmac(i, j + 1, k), 0.0) * q(i, j, k) +
                         std::min(vmac(i, j + 1, k), 0.0) * q(i, j + 1, k);
        qnew(i, j, k) = q(i, j, k) - dtdx * (fxh - fxl) - dtdy * (fyh - fyl);
      }
}
