// corpus: form=parallelfor expect=accept
// amrex_avgdown (AMReX_MultiFabUtil_3D_C.H): the coarse cell is the mean of
// its ratio[0] x ratio[1] x ratio[2] fine cells, runtime refinement ratio,
// three reference loops inside the ParallelFor (a 6-deep nest, i*ratio + m).
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void avgdown(Box const& cbx, DPGEN_IN Array4<Real const> const& fine,
                          DPGEN_OUT Array4<Real> const& crse, IntVect const& ratio) {
  const int facx = ratio[0];
  const int facy = ratio[1];
  const int facz = ratio[2];
  const Real volfrac = Real(1.0) / Real(facx * facy * facz);
  ParallelFor(cbx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    const int ii = i * facx;
    const int jj = j * facy;
    const int kk = k * facz;
    Real c = 0.0;
    for (int kref = 0; kref < facz; ++kref)
      for (int jref = 0; jref < facy; ++jref)
        for (int iref = 0; iref < facx; ++iref)
          c += fine(ii + iref, jj + jref, kk + kref);
    crse(i, j, k) = volfrac * c;
  });
}
