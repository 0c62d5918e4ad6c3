// upwind_unsigned (tests/styles/): unsigned counter and size, i++; n >= 1
// (n == 0 would make n - 1 wrap in the forward kernel too).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "upwind_unsigned_adjoint.hpp"
#include "upwind_unsigned_tangent.hpp"

DPGEN_KERNEL void upwind_unsigned(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                  DPGEN_OUT double* q_new, unsigned n, double dt_dx);

TEST_CASE("styles: upwind_unsigned") {
  for (unsigned n : {1u, 2u, 3u, 7u, 23u}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { upwind_unsigned(in[0], in[1], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      upwind_unsigned_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      upwind_unsigned_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      upwind_unsigned_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}
