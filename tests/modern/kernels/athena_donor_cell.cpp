// corpus: form=athena expect=accept
// Athena++ DonorCellX1 (src/reconstruct/dc.cpp): first-order reconstruction
// of the left/right states at x1 faces along one row (k, j), NHYDRO
// components, AthenaArray by reference; wl is written at i + 1.
#include "dpgen/annotate.hpp"

#include "athena_array.hpp"

constexpr int NHYDRO = 5;

DPGEN_KERNEL void DonorCellX1(const int k, const int j, const int il, const int iu,
                              DPGEN_IN const AthenaArray<Real>& w, DPGEN_OUT AthenaArray<Real>& wl,
                              DPGEN_OUT AthenaArray<Real>& wr) {
  for (int n = 0; n < NHYDRO; ++n) {
#pragma omp simd
    for (int i = il; i <= iu; ++i) {
      wl(n, i + 1) = w(n, k, j, i);
      wr(n, i) = w(n, k, j, i);
    }
  }
}
