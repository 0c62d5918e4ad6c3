// heat_source_readback (tests/styles/): store, read back, store again;
// leading guard; nonlinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat_source_readback_adjoint.hpp"
#include "heat_source_readback_tangent.hpp"

DPGEN_KERNEL void heat_source_readback(DPGEN_IN const double* t, DPGEN_IN const double* src,
                                       DPGEN_OUT double* t_new, int n, double r, double dt);

TEST_CASE("styles: heat_source_readback") {
  for (int n : {1, 2, 3, 4, 15}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { heat_source_readback(in[0], in[1], out[0], n, 0.2, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat_source_readback_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.2, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat_source_readback_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.2, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat_source_readback_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.2, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}
