// corpus: form=parallelfor expect=accept
// AMReX GPU-style: the loop nest is amrex::ParallelFor over the box with a
// [=] AMREX_GPU_DEVICE lambda capturing the Array4s by value.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

DPGEN_KERNEL void laplacian(amrex::Box const& bx,
                            DPGEN_IN amrex::Array4<amrex::Real const> const& phi,
                            DPGEN_OUT amrex::Array4<amrex::Real> const& lap, amrex::Real dxinv2) {
  amrex::ParallelFor(bx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    lap(i, j, k) =
        dxinv2 * (phi(i - 1, j, k) + phi(i + 1, j, k) + phi(i, j - 1, k) + phi(i, j + 1, k) +
                  phi(i, j, k - 1) + phi(i, j, k + 1) - 6.0 * phi(i, j, k));
  });
}
