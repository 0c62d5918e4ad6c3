// corpus: form=functor expect=accept
// Kokkos functor style: a struct with View members and operator()(i, j)
// const; the kernel builds it from its parameters and hands it to a
// parallel_for over an MDRangePolicy. The functor's operator() is the body.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

struct Laplace2D {
  Kokkos::View<const double**> u;
  Kokkos::View<double**> lap;
  double inv_h2;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, const int j) const {
    lap(i, j) = inv_h2 * (u(i - 1, j) + u(i + 1, j) + u(i, j - 1) + u(i, j + 1) - 4.0 * u(i, j));
  }
};

DPGEN_KERNEL void laplace2d_functor(DPGEN_IN Kokkos::View<const double**> u,
                                    DPGEN_OUT Kokkos::View<double**> lap, double h) {
  const int nx = u.extent_int(0), ny = u.extent_int(1);
  Kokkos::parallel_for("laplace2d",
                       Kokkos::MDRangePolicy<Kokkos::Rank<2>>({1, 1}, {nx - 1, ny - 1}),
                       Laplace2D{u, lap, 1.0 / (h * h)});
}
