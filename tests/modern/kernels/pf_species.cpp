// corpus: form=parallelfor expect=accept
// Multi-species diffusion with a per-species, per-cell diffusivity:
// ParallelFor(bx, ncomp, [=](int i, int j, int k, int n) {...}), component
// planes n*nstride apart.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void species_diffusion(Box const& bx, int nspec, DPGEN_IN Array4<Real const> const& Y,
                                    DPGEN_IN Array4<Real const> const& D,
                                    DPGEN_OUT Array4<Real> const& rhs, Real dxinv2) {
  ParallelFor(bx, nspec, [=] AMREX_GPU_DEVICE(int i, int j, int k, int n) noexcept {
    const Real dxp = 0.5 * (D(i, j, k, n) + D(i + 1, j, k, n));
    const Real dxm = 0.5 * (D(i, j, k, n) + D(i - 1, j, k, n));
    const Real dyp = 0.5 * (D(i, j, k, n) + D(i, j + 1, k, n));
    const Real dym = 0.5 * (D(i, j, k, n) + D(i, j - 1, k, n));
    rhs(i, j, k, n) =
        dxinv2 *
        (dxp * (Y(i + 1, j, k, n) - Y(i, j, k, n)) - dxm * (Y(i, j, k, n) - Y(i - 1, j, k, n)) +
         dyp * (Y(i, j + 1, k, n) - Y(i, j, k, n)) - dym * (Y(i, j, k, n) - Y(i, j - 1, k, n)));
  });
}
