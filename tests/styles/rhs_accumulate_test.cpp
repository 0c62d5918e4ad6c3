// rhs_accumulate (tests/styles/): in/out += accumulation into a DPGEN_OUT.
// Assumption: the output's incoming value is not differentiated (it is not a
// DPGEN_IN); the checker zeroes outputs before the forward call, and the
// adjoint keeps the design's signature (u, u_adj, f, f_adj, rhs_adj, ...).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "rhs_accumulate_adjoint.hpp"
#include "rhs_accumulate_tangent.hpp"

DPGEN_KERNEL void rhs_accumulate(DPGEN_IN const double* u, DPGEN_IN const double* f,
                                 DPGEN_OUT double* rhs, int n, double inv_h2);

TEST_CASE("styles: rhs_accumulate") {
  for (int n : {1, 2, 3, 5, 19}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { rhs_accumulate(in[0], in[1], out[0], n, 3.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      rhs_accumulate_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 3.0);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      rhs_accumulate_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 3.0);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      rhs_accumulate_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 3.0);
    };
    dpgen_test::check_adjoint(p);
  }
}
