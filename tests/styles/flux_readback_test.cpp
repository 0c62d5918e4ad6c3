// flux_readback (tests/styles/): an output read back after it is stored in
// the same iteration; nonlinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "flux_readback_adjoint.hpp"
#include "flux_readback_tangent.hpp"

DPGEN_KERNEL void flux_readback(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                                DPGEN_OUT double* flux, DPGEN_OUT double* dq, int n,
                                double inv_dx);

TEST_CASE("styles: flux_readback") {
  for (int n : {1, 2, 3, 9, 24}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { flux_readback(in[0], in[1], out[0], out[1], n, 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flux_readback_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], n, 2.0);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flux_readback_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], seed[1], out_n[1], n, 2.0);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      flux_readback_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], out[1], outd[1], n, 2.0);
    };
    dpgen_test::check_adjoint(p);
  }
}
