// corpus: form=member expect=accept
// A Kokkos-style solver class: View members, the kernel a const method that
// runs a parallel_for with KOKKOS_CLASS_LAMBDA ([=, *this]). Upwind
// advection with positive Courant numbers; the velocity is a member View too.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

struct UpwindAdvection {
  Kokkos::View<const double**> q DPGEN_IN;
  Kokkos::View<const double**> speed DPGEN_IN; // local speed factor, > 0
  Kokkos::View<double**> q_new DPGEN_OUT;
  double cx = 0.3, cy = 0.2;

  DPGEN_KERNEL void advance() const {
    const int nx = q.extent_int(0), ny = q.extent_int(1);
    Kokkos::parallel_for(
        "advance", Kokkos::MDRangePolicy<Kokkos::Rank<2>>({1, 1}, {nx, ny}),
        KOKKOS_CLASS_LAMBDA(const int i, const int j) {
          q_new(i, j) =
              q(i, j) - speed(i, j) * (cx * (q(i, j) - q(i - 1, j)) + cy * (q(i, j) - q(i, j - 1)));
        });
  }
};
