// PdV work in a 1D Lagrangian hydro cell, Fortran-style interface: every
// scalar (bounds, dt) arrives by pointer and is copied to a local.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void pdv_ptrscalars(const int* xmin, const int* xmax, const double* dt,
                                 DPGEN_IN const double* density, DPGEN_IN const double* pressure,
                                 DPGEN_IN const double* volume, DPGEN_IN const double* xvel,
                                 DPGEN_OUT double* energy_change) {
  int x_min = *xmin;
  int x_max = *xmax;
  double dtv = *dt;
  for (int j = x_min; j <= x_max; ++j) {
    double dv = 0.5 * dtv * (xvel[j + 1] - xvel[j]);
    double vol_new = volume[j] + dv;
    energy_change[j] = -pressure[j] * dv / (density[j] * vol_new);
  }
}
