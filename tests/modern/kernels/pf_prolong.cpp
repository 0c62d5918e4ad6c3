// corpus: form=parallelfor expect=accept
// Linear prolongation with a runtime ratio, written over coarse cells: each
// coarse cell fills its ratio^2 fine cells (index ic*ratio + m), from
// centered slopes (2D: k is one plane).
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void prolong_linear(Box const& cbx, DPGEN_IN Array4<Real const> const& crse,
                                 DPGEN_OUT Array4<Real> const& fine, int ratio) {
  const Real rinv = Real(1.0) / ratio;
  ParallelFor(cbx, [=] AMREX_GPU_DEVICE(int ic, int jc, int kc) noexcept {
    const Real sx = 0.5 * (crse(ic + 1, jc, kc) - crse(ic - 1, jc, kc));
    const Real sy = 0.5 * (crse(ic, jc + 1, kc) - crse(ic, jc - 1, kc));
    for (int jj = 0; jj < ratio; ++jj)
      for (int ii = 0; ii < ratio; ++ii) {
        const Real xoff = (ii + 0.5) * rinv - 0.5;
        const Real yoff = (jj + 0.5) * rinv - 0.5;
        fine(ic * ratio + ii, jc * ratio + jj, kc) = crse(ic, jc, kc) + xoff * sx + yoff * sy;
      }
  });
}
