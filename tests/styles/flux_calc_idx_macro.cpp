// A hydro mini-app's flux kernel behind a Fortran interface, as written
// (issue 20, defect 5): sizes and dt arrive by pointer and are copied into
// locals, arrays are flat with ghost cells, and every index goes through an
// index macro with the lower bounds folded in. Affine after expansion, so
// the adjoint is in gather form (it was scatter form, serial).
#include "dpgen/annotate.hpp"

#define IDX(i, j) ((i) - (x_min - 2) + ((j) - (y_min - 2)) * (x_max + 5))

DPGEN_KERNEL void flux_calc_idx_macro(const int* xmin, const int* xmax, const int* ymin,
                                      const int* ymax, const double* dt_p,
                                      DPGEN_IN const double* xarea, DPGEN_IN const double* xvel0,
                                      DPGEN_IN const double* xvel1, DPGEN_OUT double* vol_flux_x) {
  int x_min = *xmin, x_max = *xmax, y_min = *ymin, y_max = *ymax;
  double dt = *dt_p;
  int j, k;
  for (k = y_min; k <= y_max; k++) {
    for (j = x_min; j <= x_max + 1; j++) {
      vol_flux_x[IDX(j, k)] =
          0.25 * dt * xarea[IDX(j, k)] *
          (xvel0[IDX(j, k)] + xvel0[IDX(j, k + 1)] + xvel1[IDX(j, k)] * xvel1[IDX(j, k + 1)]);
    }
  }
}
