// corpus: form=reject expect=reject
// reason: two views of one output (rhs is a copy of dq): iteration i stores dq(i) and
//   subtracts from rhs(i - 1), the element iteration i - 1 stored; an element written by
//   two iterations (a race in ParallelFor), no write-once output
//
// Aliasing output views: a copy of an Array4 is a second handle on the same
// data; the flux is added to one cell through dq and taken from the
// neighbour through rhs.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void flux_update_alias(Box const& bx, DPGEN_IN Array4<Real const> const& q,
                                    DPGEN_OUT Array4<Real> const& dq) {
  Array4<Real> const rhs = dq;
  ParallelFor(bx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    const Real f = q(i, j, k) * q(i, j, k) - q(i - 1, j, k) * q(i - 1, j, k);
    dq(i, j, k) = f;
    rhs(i - 1, j, k) -= f;
  });
}
