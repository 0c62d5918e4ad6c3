// view_fortran3d (tests/styles/): a column-major 3D view with ghost cells
// below index 0 (i from -1), by const reference, bounds from its members; an
// upwind difference in i whose direction depends on the sign of a velocity.
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

DPGEN_KERNEL void view_fortran3d(DPGEN_IN const grid::FortranView3D& q,
                                 DPGEN_IN const grid::FortranView3D& vel,
                                 DPGEN_OUT const grid::FortranView3D& dq, double dt_dx) {
  for (int k = 0; k < q.nk; ++k)
    for (int j = 0; j < q.nj; ++j)
      for (int i = 0; i < q.ni + q.ilo - 1; ++i) {
        const double u = vel(i, j, k);
        dq(i, j, k) = u > 0.0 ? -dt_dx * u * (q(i, j, k) - q(i - 1, j, k))
                              : -dt_dx * u * (q(i + 1, j, k) - q(i, j, k));
      }
}
