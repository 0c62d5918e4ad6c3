// hydro_twopass_workarray (tests/styles/): fluxes in a work array read by a
// second nest; nonlinear, piecewise (max, |.|).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "hydro_twopass_workarray_adjoint.hpp"
#include "hydro_twopass_workarray_tangent.hpp"

DPGEN_KERNEL void hydro_twopass_workarray(DPGEN_IN const double* q, DPGEN_OUT double* flux,
                                          DPGEN_OUT double* q_new, int n, double dt_dx);

TEST_CASE("styles: hydro_twopass_workarray") {
  for (int n : {1, 2, 3, 6, 20}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { hydro_twopass_workarray(in[0], out[0], out[1], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      hydro_twopass_workarray_adjoint(in[0], adj[0], seed[0], seed[1], n, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      hydro_twopass_workarray_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      hydro_twopass_workarray_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}
