// corpus: form=kokkos expect=accept
// 2D shallow water, Lax-Friedrichs step on the interior: three conserved
// fields as Views (h, hu, hv), fluxes from helper functions, three outputs.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

KOKKOS_INLINE_FUNCTION double flux_mx(double h, double hu, double g) {
  return hu * hu / h + 0.5 * g * h * h;
}
KOKKOS_INLINE_FUNCTION double flux_cross(double h, double a, double b) { return a * b / h; }

DPGEN_KERNEL void swe_lax_friedrichs(DPGEN_IN Kokkos::View<const double**> h,
                                     DPGEN_IN Kokkos::View<const double**> hu,
                                     DPGEN_IN Kokkos::View<const double**> hv,
                                     DPGEN_OUT Kokkos::View<double**> h_new,
                                     DPGEN_OUT Kokkos::View<double**> hu_new,
                                     DPGEN_OUT Kokkos::View<double**> hv_new, double dtdx,
                                     double dtdy, double g) {
  const int nx = h.extent_int(0), ny = h.extent_int(1);
  Kokkos::parallel_for(
      "swe_lf", Kokkos::MDRangePolicy<Kokkos::Rank<2>>({1, 1}, {nx - 1, ny - 1}),
      KOKKOS_LAMBDA(const int i, const int j) {
        const double havg = 0.25 * (h(i + 1, j) + h(i - 1, j) + h(i, j + 1) + h(i, j - 1));
        const double huavg = 0.25 * (hu(i + 1, j) + hu(i - 1, j) + hu(i, j + 1) + hu(i, j - 1));
        const double hvavg = 0.25 * (hv(i + 1, j) + hv(i - 1, j) + hv(i, j + 1) + hv(i, j - 1));
        h_new(i, j) = havg - 0.5 * dtdx * (hu(i + 1, j) - hu(i - 1, j)) -
                      0.5 * dtdy * (hv(i, j + 1) - hv(i, j - 1));
        hu_new(i, j) =
            huavg -
            0.5 * dtdx *
                (flux_mx(h(i + 1, j), hu(i + 1, j), g) - flux_mx(h(i - 1, j), hu(i - 1, j), g)) -
            0.5 * dtdy *
                (flux_cross(h(i, j + 1), hu(i, j + 1), hv(i, j + 1)) -
                 flux_cross(h(i, j - 1), hu(i, j - 1), hv(i, j - 1)));
        hv_new(i, j) =
            hvavg -
            0.5 * dtdx *
                (flux_cross(h(i + 1, j), hu(i + 1, j), hv(i + 1, j)) -
                 flux_cross(h(i - 1, j), hu(i - 1, j), hv(i - 1, j))) -
            0.5 * dtdy *
                (flux_mx(h(i, j + 1), hv(i, j + 1), g) - flux_mx(h(i, j - 1), hv(i, j - 1), g));
      });
}
