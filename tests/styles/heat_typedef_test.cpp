// heat_typedef (tests/styles/): `typedef double FLOAT;` in the signature.
// The generated header must compile on its own (FLOAT declared or spelled
// as double); the test includes it before anything that defines FLOAT.
#include "heat_typedef_adjoint.hpp"
#include "heat_typedef_tangent.hpp"

#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat_typedef(DPGEN_IN const double* u, DPGEN_IN const double* alpha,
                               DPGEN_OUT double* u_new, int n, double r);

TEST_CASE("styles: heat_typedef") {
  for (int n : {1, 2, 3, 12}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { heat_typedef(in[0], in[1], out[0], n, 0.25); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat_typedef_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.25);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat_typedef_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.25);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat_typedef_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.25);
    };
    dpgen_test::check_adjoint(p);
  }
}
