// corpus: form=deep expect=accept
// Runtime-ratio transfers that fit in two loops (the product i*ratio + m
// without the extra depth): averaging restriction and linear-in-cell
// prolongation with slopes.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void restrict_ratio(DPGEN_IN const double* fine, DPGEN_OUT double* crse, int nc,
                                 int ratio) {
  for (int ic = 0; ic < nc; ++ic) {
    double s = 0.0;
    for (int m = 0; m < ratio; ++m)
      s += fine[ic * ratio + m];
    crse[ic] = s / ratio;
  }
}

DPGEN_KERNEL void prolong_ratio(DPGEN_IN const double* crse, DPGEN_OUT double* fine, int nc,
                                int ratio) {
  for (int ic = 1; ic < nc - 1; ++ic) {
    const double slope = 0.5 * (crse[ic + 1] - crse[ic - 1]);
    for (int m = 0; m < ratio; ++m)
      fine[ic * ratio + m] = crse[ic] + ((m + 0.5) / ratio - 0.5) * slope;
  }
}
