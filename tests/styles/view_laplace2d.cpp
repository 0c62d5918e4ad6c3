// view_laplace2d (tests/styles/): a user's own 2D view class taken by value,
// sizes from its members and methods, grid constants from an object; a
// nonlinear term (u * u) so that the adjoint reads the primal through the view.
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
