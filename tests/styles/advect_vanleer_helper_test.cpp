// advect_vanleer_helper (tests/styles/): two helpers (limiter, flux);
// nonlinear, piecewise.
#include "support/adjoint_check.hpp"

#include "advect_vanleer_helper_adjoint.hpp"
#include "advect_vanleer_helper_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void advect_vanleer_helper(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                        DPGEN_OUT double* flux, int n);

TEST_CASE("styles: advect_vanleer_helper") {
  for (int n : {1, 3, 4, 10, 26}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { advect_vanleer_helper(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect_vanleer_helper_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      advect_vanleer_helper_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      advect_vanleer_helper_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
