// corpus: form=reject expect=reject
// reason: an in-place Gauss-Seidel sweep in a ParallelFor: each iteration reads neighbours
//   that other iterations overwrite (a loop-carried dependence, a race in parallel); write
//   the new values to a separate output (Jacobi) or split the colours
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void gs_sweep(Box const& bx, DPGEN_INOUT Array4<Real> const& phi,
                           Array4<Real const> const& rhs, Real h2) {
  ParallelFor(bx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    phi(i, j, k) = (phi(i - 1, j, k) + phi(i + 1, j, k) + phi(i, j - 1, k) + phi(i, j + 1, k) +
                    phi(i, j, k - 1) + phi(i, j, k + 1) - h2 * rhs(i, j, k)) /
                   6.0;
  });
}
