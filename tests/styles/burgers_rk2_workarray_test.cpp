// burgers_rk2_workarray (tests/styles/): nests feeding each other through a
// work array (itself a DPGEN_OUT, so it has a seed too); nonlinear.
#include "support/adjoint_check.hpp"

#include "burgers_rk2_workarray_adjoint.hpp"
#include "burgers_rk2_workarray_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void burgers_rk2_workarray(DPGEN_IN const double* u, DPGEN_OUT double* work,
                                        DPGEN_OUT double* u_next, int n, double c);

TEST_CASE("styles: burgers_rk2_workarray") {
  for (int n : {1, 3, 4, 5, 18}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { burgers_rk2_workarray(in[0], out[0], out[1], n, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      burgers_rk2_workarray_adjoint(in[0], adj[0], seed[0], seed[1], n, 0.2);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      burgers_rk2_workarray_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n, 0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      burgers_rk2_workarray_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n, 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}
