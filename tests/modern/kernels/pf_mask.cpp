// corpus: form=mask expect=accept
// An integer mask Array4 (AMReX iMultiFab: 1 = covered by a finer level):
// covered cells keep their value, the others get a smoothing step. The mask
// is not differentiated.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void masked_smooth(Box const& bx, Array4<int const> const& covered,
                                DPGEN_IN Array4<Real const> const& phi,
                                DPGEN_OUT Array4<Real> const& out, Real w) {
  ParallelFor(bx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    if (covered(i, j, k)) {
      out(i, j, k) = phi(i, j, k);
    } else {
      out(i, j, k) =
          (1.0 - w) * phi(i, j, k) +
          0.25 * w * (phi(i - 1, j, k) + phi(i + 1, j, k) + phi(i, j - 1, k) + phi(i, j + 1, k));
    }
  });
}
