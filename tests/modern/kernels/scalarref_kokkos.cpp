// corpus: form=scalarref expect=accept
// An error norm into a double& (what a Kokkos code without parallel_reduce
// writes on the host), Views by value, dx by const reference, the exact
// solution an unmarked (constant) View.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

DPGEN_KERNEL void l2_error(DPGEN_IN Kokkos::View<const double*> u,
                           Kokkos::View<const double*> u_exact, const double& dx,
                           DPGEN_OUT double& err2) {
  err2 = 0.0;
  for (std::size_t i = 0; i < u.extent(0); ++i) {
    const double e = u(i) - u_exact(i);
    err2 += e * e * dx;
  }
}
