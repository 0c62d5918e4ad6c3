// compound_scale (tests/styles/): `*=` and `/=` on an output element that the
// iteration has stored (a `*=` on an element with no store before it in the
// iteration is refused: tests/diagnostics/compound_output.cpp); nonlinear.
#include "support/adjoint_check.hpp"

#include "compound_scale_adjoint.hpp"
#include "compound_scale_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void compound_scale(DPGEN_IN const double* q, DPGEN_IN const double* area,
                                 DPGEN_IN const double* vol, DPGEN_OUT double* f, int n);

TEST_CASE("styles: compound_scale") {
  for (int n : {1, 2, 3, 17}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn, sn, sn};
    p.out_sizes = {sn};
    p.forward = [&](auto in, auto out) { compound_scale(in[0], in[1], in[2], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      compound_scale_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      compound_scale_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
