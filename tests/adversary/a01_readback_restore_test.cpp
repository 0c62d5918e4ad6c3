#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a01_readback_restore_adjoint.hpp"
#include "a01_readback_restore_tangent.hpp"

DPGEN_KERNEL void a01_readback_restore(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                       DPGEN_OUT double* u, int n);
TEST_CASE("adversary: a01_readback_restore") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a01_readback_restore(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a01_readback_restore_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a01_readback_restore_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
