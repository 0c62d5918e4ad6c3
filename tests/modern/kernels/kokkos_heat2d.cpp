// corpus: form=kokkos expect=accept
// Kokkos tutorial style: Views by value, sizes from extent(), the loop nest a
// labelled parallel_for over an MDRangePolicy<Rank<2>> with a KOKKOS_LAMBDA.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

DPGEN_KERNEL void heat2d_step(DPGEN_IN Kokkos::View<const double**> u,
                              DPGEN_OUT Kokkos::View<double**> unew, const double alpha) {
  const int nx = u.extent_int(0);
  const int ny = u.extent_int(1);
  Kokkos::parallel_for(
      "heat2d_step", Kokkos::MDRangePolicy<Kokkos::Rank<2>>({1, 1}, {nx - 1, ny - 1}),
      KOKKOS_LAMBDA(const int i, const int j) {
        unew(i, j) = u(i, j) + alpha * (u(i - 1, j) + u(i + 1, j) + u(i, j - 1) + u(i, j + 1) -
                                        4.0 * u(i, j));
      });
}
