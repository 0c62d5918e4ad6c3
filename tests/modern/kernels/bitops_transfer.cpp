// corpus: form=bitops expect=accept
// Multigrid transfers on vertex-centered 1D grids (nf = 2 nc - 1) written
// with shifts, as geometric-multigrid benchmarks do: full-weighting
// restriction reads fine[(i << 1) + m]; linear prolongation takes
// coarse[i >> 1] and, for odd i (i & 1), the average of two coarse values.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void restrict_fw(DPGEN_IN const double* fine, DPGEN_OUT double* coarse, int nc) {
  coarse[0] = fine[0];
  for (int i = 1; i < nc - 1; ++i) {
    const int f = i << 1;
    coarse[i] = 0.25 * fine[f - 1] + 0.5 * fine[f] + 0.25 * fine[f + 1];
  }
  coarse[nc - 1] = fine[(nc - 1) << 1];
}

DPGEN_KERNEL void prolong_bits(DPGEN_IN const double* coarse, DPGEN_OUT double* fine, int nf) {
  for (int i = 0; i < nf - 1; ++i) {
    const int ic = i >> 1;
    fine[i] = (i & 1) ? 0.5 * (coarse[ic] + coarse[ic + 1]) : coarse[ic];
  }
  fine[nf - 1] = coarse[(nf - 1) >> 1];
}
