// corpus: form=reject expect=reject
// reason: a ParallelFor body adds into a scalar captured by reference: a data race under
//   the library's parallel semantics (and no device lambda can capture host memory by
//   reference); the reduction needs ParallelReduce / parallel_reduce. (Debatable: as a
//   serial loop nest it is a plain sum; rejecting is the safe reading.)
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void box_sum_sq(Box const& bx, DPGEN_IN Array4<Real const> const& a,
                             DPGEN_OUT Real& sum) {
  sum = 0.0;
  ParallelFor(bx, [&](int i, int j, int k) noexcept { sum += a(i, j, k) * a(i, j, k); });
}
