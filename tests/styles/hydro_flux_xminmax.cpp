// Volume flux through x faces in the style of a Fortran-derived hydro
// mini-app: bounds x_min..x_max / y_min..y_max (inclusive, 1-based), two halo
// cells on each side giving the leading dimension, every scalar by pointer.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void hydro_flux_xminmax(const int* xmin, const int* xmax, const int* ymin,
                                     const int* ymax, const double* dt,
                                     DPGEN_IN const double* xarea, DPGEN_IN const double* xvel0,
                                     DPGEN_IN const double* xvel1, DPGEN_OUT double* vol_flux_x) {
  int x_min = *xmin;
  int x_max = *xmax;
  int y_min = *ymin;
  int y_max = *ymax;
  int ld = x_max - x_min + 5;
  for (int k = y_min; k <= y_max; k++) {
    for (int j = x_min; j <= x_max + 1; j++) {
      int c = (k - y_min + 2) * ld + (j - x_min + 2);
      vol_flux_x[c] = 0.25 * (*dt) * xarea[c] *
                      (xvel0[c] + xvel0[c + ld] + xvel1[c] + xvel1[c + ld]);
    }
  }
}
