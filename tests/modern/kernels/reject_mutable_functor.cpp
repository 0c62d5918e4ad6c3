// corpus: form=reject expect=reject
// reason: the functor carries state between iterations in a mutable member (a running sum
//   read by the next iteration): a race under parallel_for and a loop-carried value; a
//   prefix sum needs parallel_scan, or a separate output
//
// A functor with mutable state: a "prefix sum" through parallel_for.
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

struct RunningSum {
  Kokkos::View<const double*> u;
  Kokkos::View<double*> out;
  mutable double acc = 0.0;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    acc += u(i) * u(i);
    out(i) = acc;
  }
};

DPGEN_KERNEL void running_energy(DPGEN_IN Kokkos::View<const double*> u,
                                 DPGEN_OUT Kokkos::View<double*> out) {
  Kokkos::parallel_for("running", Kokkos::RangePolicy<>(0, u.extent_int(0)), RunningSum{u, out});
}
