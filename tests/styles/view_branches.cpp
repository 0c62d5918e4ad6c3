// A view's element read inside a branch into a local (`left = q(j, i - 1)`
// under `if (i > 0)`, an if/else, a switch): the first read of a view may come
// in an arm, and the value merged after the if must keep the view's layout
// (dpgen used to put its placeholder row length into the index there,
// reading a wrong element with no message).
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

DPGEN_KERNEL void view_left_in_branch(DPGEN_IN grid::View2D<const double> q,
                                      DPGEN_OUT grid::View2D<double> r) {
  for (int j = 0; j < q.rows(); ++j)
    for (int i = 0; i < q.cols(); ++i) {
      double left = 0.0;
      if (i > 0)
        left = q(j, i - 1);
      r(j, i) = q(j, i) * left;
    }
}

DPGEN_KERNEL void view_upwind_arms(DPGEN_IN grid::View2D<const double> q,
                                   DPGEN_IN grid::View2D<const double> u,
                                   DPGEN_OUT grid::View2D<double> r, int kind) {
  for (int j = 1; j < q.rows(); ++j)
    for (int i = 1; i < q.cols(); ++i) {
      double f;
      if (u(j, i) > 0.0)
        f = q(j, i - 1);
      else
        f = q(j - 1, i);
      double g = 0.0;
      switch (kind) {
      case 0:
        g = q(j - 1, i - 1);
        break;
      default:
        g = u(j, i - 1) * q(j, i);
        break;
      }
      r(j, i) = u(j, i) * f + g;
    }
}
