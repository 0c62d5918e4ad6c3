// corpus: form=athena expect=accept
// Athena++ Hydro::AddFluxDivergence (src/hydro/hydro.cpp, uniform Cartesian
// mesh): dU/dt from x1 and x2 fluxes, a 4-deep n, k, j, i nest with the
// is..ie bounds of the mesh block.
#include "dpgen/annotate.hpp"

#include "athena_array.hpp"

DPGEN_KERNEL void AddFluxDivergence(const Real wght, DPGEN_IN const AthenaArray<Real>& x1flux,
                                    DPGEN_IN const AthenaArray<Real>& x2flux,
                                    DPGEN_OUT AthenaArray<Real>& du, int nhydro, int is, int ie,
                                    int js, int je, int ks, int ke, Real dx1, Real dx2) {
  for (int n = 0; n < nhydro; ++n) {
    for (int k = ks; k <= ke; ++k) {
      for (int j = js; j <= je; ++j) {
#pragma omp simd
        for (int i = is; i <= ie; ++i) {
          Real dflx = (x1flux(n, k, j, i + 1) - x1flux(n, k, j, i)) / dx1;
          dflx += (x2flux(n, k, j + 1, i) - x2flux(n, k, j, i)) / dx2;
          du(n, k, j, i) = -wght * dflx;
        }
      }
    }
  }
}
