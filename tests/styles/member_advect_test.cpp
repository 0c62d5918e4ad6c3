// member_advect (tests/styles/): Advection1D_step_adjoint(self, dt, q__adj,
// q_new__adj) reads the object's members, private ones included.
#include "support/adjoint_check.hpp"

#include "include/member_classes.hpp"
#include "member_advect_adjoint.hpp"
#include "member_advect_tangent.hpp"

TEST_CASE("styles: member_advect") {
  for (double c : {0.7, -0.4})
    for (int n : {2, 3, 9}) {
      CAPTURE(c);
      CAPTURE(n);
      dpgen_test::Problem<double> p;
      p.in_sizes = {size_t(n)};
      p.out_sizes = {size_t(n)};
      p.forward = [&](auto in, auto out) { Advection1D(n, c, in[0], out[0]).step(0.3); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        const Advection1D self(n, c, in[0], nullptr); // (no primal output needed)
        Advection1D_step_adjoint(self, 0.3, adj[0], seed[0]);
      };
      p.tangent = [&](auto in, auto d, auto out, auto dout) {
        const Advection1D self(n, c, in[0], out[0]);
        Advection1D_step_tangent(self, 0.3, d[0], dout[0]);
      };
      dpgen_test::check_adjoint(p);
    }
}
