// view_laplace2d (tests/styles/): a user's own 2D view class taken by value,
// sizes from its members and methods, grid constants from an object; a
// nonlinear term (u * u) so that the adjoint reads the primal through the view;
// a doubly periodic upwind step whose wrapped neighbours are conditional indices.
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

DPGEN_KERNEL void view_laplace2d(DPGEN_IN grid::View2D<const double> u,
                                 DPGEN_OUT grid::View2D<double> v, const grid::Spacing& h,
                                 double kappa) {
  const int nx = u.cols(), ny = u.rows();
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      v(j, i) = kappa * h.inv_dx2() * (u(j, i - 1) + u(j, i + 1) - 2.0 * u(j, i)) +
                kappa / (h.dy * h.dy) * (u(j - 1, i) + u(j + 1, i) - 2.0 * u(j, i)) -
                u(j, i) * u(j, i);
}

// Upwind advection on a doubly periodic grid: the neighbours wrap around
// through conditional indices (`im = i == 0 ? nx - 1 : i - 1`), as codes
// without ghost cells write it.
DPGEN_KERNEL void view_periodic_upwind(DPGEN_IN grid::View2D<const double> q,
                                       DPGEN_OUT grid::View2D<double> qn, double cx, double cy) {
  const int nx = q.cols(), ny = q.rows();
  for (int j = 0; j < ny; ++j) {
    const int jm = j == 0 ? ny - 1 : j - 1;
    for (int i = 0; i < nx; ++i) {
      const int im = (i == 0) ? nx - 1 : i - 1;
      const int ip = (i + 1 == nx) ? 0 : i + 1;
      qn(j, i) = q(j, i) - cx * (q(j, i) - q(j, im)) - cy * (q(j, i) - q(jm, i)) +
                 0.1 * q(j, ip) * q(jm, im);
    }
  }
}
