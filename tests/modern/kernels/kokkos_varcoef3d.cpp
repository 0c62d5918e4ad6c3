// corpus: form=kokkos expect=accept
// Variable-coefficient 3D operator -div(kappa grad p) on the interior
// (a mini-app's residual kernel), MDRangePolicy<Rank<3>>, no label.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

DPGEN_KERNEL void varcoef_apply(DPGEN_IN Kokkos::View<const double***> kappa,
                                DPGEN_IN Kokkos::View<const double***> p,
                                DPGEN_OUT Kokkos::View<double***> Ap, double inv_h2) {
  const int n0 = kappa.extent_int(0), n1 = kappa.extent_int(1), n2 = kappa.extent_int(2);
  Kokkos::parallel_for(
      Kokkos::MDRangePolicy<Kokkos::Rank<3>>({1, 1, 1}, {n0 - 1, n1 - 1, n2 - 1}),
      KOKKOS_LAMBDA(int i, int j, int k) {
        auto face = [&](int a, int b, int c) { return 0.5 * (kappa(i, j, k) + kappa(a, b, c)); };
        Ap(i, j, k) = -inv_h2 * (face(i + 1, j, k) * (p(i + 1, j, k) - p(i, j, k)) -
                                 face(i - 1, j, k) * (p(i, j, k) - p(i - 1, j, k)) +
                                 face(i, j + 1, k) * (p(i, j + 1, k) - p(i, j, k)) -
                                 face(i, j - 1, k) * (p(i, j, k) - p(i, j - 1, k)) +
                                 face(i, j, k + 1) * (p(i, j, k + 1) - p(i, j, k)) -
                                 face(i, j, k - 1) * (p(i, j, k) - p(i, j, k - 1)));
      });
}
