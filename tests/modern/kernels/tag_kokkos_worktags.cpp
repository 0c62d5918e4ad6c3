// corpus: form=tag expect=accept
// Kokkos work tags: one functor, two operator() overloads selected by an
// unnamed tag argument; MDRangePolicy<Tag, Rank<2>> picks the overload.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

struct FaceX {};
struct FaceY {};

struct GradientFluxes {
  Kokkos::View<const double**> phi;
  Kokkos::View<double**> fx, fy;
  double inv_dx, inv_dy;
  KOKKOS_INLINE_FUNCTION void operator()(FaceX, const int i, const int j) const {
    fx(i, j) = (phi(i, j) - phi(i - 1, j)) * inv_dx;
  }
  KOKKOS_INLINE_FUNCTION void operator()(FaceY, const int i, const int j) const {
    fy(i, j) = (phi(i, j) - phi(i, j - 1)) * inv_dy;
  }
};

DPGEN_KERNEL void gradient_fluxes(DPGEN_IN Kokkos::View<const double**> phi,
                                  DPGEN_OUT Kokkos::View<double**> fx,
                                  DPGEN_OUT Kokkos::View<double**> fy, double dx, double dy) {
  const int nx = phi.extent_int(0), ny = phi.extent_int(1);
  const GradientFluxes f{phi, fx, fy, 1.0 / dx, 1.0 / dy};
  Kokkos::parallel_for(Kokkos::MDRangePolicy<FaceX, Kokkos::Rank<2>>({1, 0}, {nx, ny}), f);
  Kokkos::parallel_for(Kokkos::MDRangePolicy<FaceY, Kokkos::Rank<2>>({0, 1}, {nx, ny}), f);
}
