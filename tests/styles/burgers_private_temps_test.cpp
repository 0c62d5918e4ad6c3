// burgers_private_temps (tests/styles/): function-scope temporaries;
// nonlinear, piecewise (upwind switch).
#include "support/adjoint_check.hpp"

#include "burgers_private_temps_adjoint.hpp"
#include "burgers_private_temps_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void burgers_private_temps(DPGEN_IN const double* u, DPGEN_OUT double* u_next, int n,
                                        double dt, double dx, double nu);

TEST_CASE("styles: burgers_private_temps") {
  for (int n : {1, 2, 3, 7, 25}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { burgers_private_temps(in[0], out[0], n, 0.01, 0.1, 0.05); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      burgers_private_temps_adjoint(in[0], adj[0], seed[0], n, 0.01, 0.1, 0.05);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      burgers_private_temps_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.01, 0.1, 0.05);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      burgers_private_temps_tangent(in[0], dir[0], out[0], outd[0], n, 0.01, 0.1, 0.05);
    };
    dpgen_test::check_adjoint(p);
  }
}
