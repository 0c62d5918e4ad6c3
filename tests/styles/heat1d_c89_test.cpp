// heat1d_c89 (tests/styles/): C89 counter, i++; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat1d_c89_adjoint.hpp"
#include "heat1d_c89_tangent.hpp"

DPGEN_KERNEL void heat1d_c89(DPGEN_IN const double* u, DPGEN_OUT double* u_new, int n, double r);

TEST_CASE("styles: heat1d_c89") {
  for (int n : {1, 2, 3, 4, 17}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { heat1d_c89(in[0], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat1d_c89_adjoint(in[0], adj[0], seed[0], n, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat1d_c89_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat1d_c89_tangent(in[0], dir[0], out[0], outd[0], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}
