// member_functor (tests/styles/): a functor over views run on *this by a
// parallel-for of the user's own (a template helper looping over the
// interior), from a member kernel; and a free kernel that builds the same
// functor as a temporary from its own views and a computed coefficient.
#include "include/member_classes.hpp"

template <typename F> void interior_for(int ny, int nx, const F& f) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      f(j, i);
}

void Smoother2D::run() const { interior_for(u.rows(), u.cols(), *this); }

DPGEN_KERNEL void smooth_free(DPGEN_IN grid::View2D<const double> u,
                              DPGEN_IN grid::View2D<const double> w,
                              DPGEN_OUT grid::View2D<double> out, double dt) {
  interior_for(u.rows(), u.cols(), Smoother2D{u, w, out, 0.5 * dt});
}
