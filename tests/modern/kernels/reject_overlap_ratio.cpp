// corpus: form=reject expect=reject
// reason: the ratio loop runs m = 0..ratio inclusive (an off-by-one common in hand-written
//   prolongations): fine[ic*ratio + ratio] is also fine[(ic+1)*ratio + 0], written by two
//   coarse iterations, so the output is not written once and the gather adjoint would be
//   wrong; the prover must not accept products of sizes and counters it cannot separate
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void prolong_overlap(DPGEN_IN const double* crse, DPGEN_OUT double* fine, int nc,
                                  int ratio) {
  for (int ic = 0; ic < nc; ++ic)
    for (int m = 0; m <= ratio; ++m)
      fine[ic * ratio + m] = crse[ic] * (1.0 + 0.1 * m) + crse[ic] * crse[ic];
}
