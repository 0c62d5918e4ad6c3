// corpus: form=kokkos expect=accept
// Leapfrog wave equation, RangePolicy over the interior, two input Views.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

using view_type = Kokkos::View<double*>;
using const_view_type = Kokkos::View<const double*>;

DPGEN_KERNEL void wave1d_step(DPGEN_IN const_view_type u, DPGEN_IN const_view_type u_old,
                              DPGEN_OUT view_type u_new, double c2) {
  const int n = static_cast<int>(u.extent(0));
  Kokkos::parallel_for(
      "wave1d", Kokkos::RangePolicy<>(1, n - 1), KOKKOS_LAMBDA(const int i) {
        u_new(i) = 2.0 * u(i) - u_old(i) + c2 * (u(i + 1) - 2.0 * u(i) + u(i - 1));
      });
}
