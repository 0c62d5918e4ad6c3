// corpus: form=functor expect=accept
// A functor that runs itself: annotated View members, operator()(i) const is
// the loop body, run() (the kernel) launches parallel_for(policy, *this).
// Adjoint: Smooth1D_run_adjoint(const Smooth1D& self, <u adj>, <w adj>, <out seed>)
#include "dpgen/annotate.hpp"

#include "kokkos_lite.hpp"

struct Smooth1D {
  Kokkos::View<const double*> u DPGEN_IN;
  Kokkos::View<const double*> w DPGEN_IN; // per-cell smoothing weight
  Kokkos::View<double*> out DPGEN_OUT;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    out(i) = u(i) + w(i) * (u(i - 1) - 2.0 * u(i) + u(i + 1));
  }

  DPGEN_KERNEL void run() const {
    const int n = u.extent_int(0);
    Kokkos::parallel_for("smooth", Kokkos::RangePolicy<>(1, n - 1), *this);
  }
};
