#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a11_carried_readback_adjoint.hpp"
#include "a11_carried_readback_tangent.hpp"

DPGEN_KERNEL void a11_carried_readback(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                       DPGEN_OUT double* v, int n);
TEST_CASE("adversary: a11_carried_readback") {
  for (int n : {1, 2, 3, 7}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { a11_carried_readback(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a11_carried_readback_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a11_carried_readback_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
