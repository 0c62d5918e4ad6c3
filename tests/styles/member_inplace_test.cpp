// member_inplace (tests/styles/): the wrappers Reaction1D_step_adjoint and
// Reaction1D_step_tangent of an in-place member array. The adjoint takes the
// seed of the new u in u_adj and returns the adjoint of the old u there; the
// tangent updates u and u_dot in place. Both against the checker's
// differences, and the tangent's u bit for bit against the kernel.
#include "support/adjoint_check.hpp"

#include "include/member_classes.hpp"
#include "member_inplace_adjoint.hpp"
#include "member_inplace_tangent.hpp"
#include "same_bits.hpp"

#include <algorithm>
#include <vector>

TEST_CASE("styles: member_inplace") {
  for (int n : {0, 1, 2, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    const double dt = 0.3;
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N}; // u before the step, rate
    p.out_sizes = {N};   // u after it
    p.forward = [&](auto in, auto out) {
      std::copy(in[0], in[0] + N, out[0]);
      Reaction1D{n, out[0], in[1]}.step(dt);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> u(in[0], in[0] + N), u_adj(seed[0], seed[0] + N);
      Reaction1D_step_adjoint(Reaction1D{n, u.data(), in[1]}, dt, u_adj.data(), adj[1]);
      for (size_t i = 0; i < N; ++i)
        adj[0][i] += u_adj[i];
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      std::copy(in[0], in[0] + N, out[0]);
      std::copy(d[0], d[0] + N, dout[0]);
      Reaction1D_step_tangent(Reaction1D{n, out[0], in[1]}, dt, dout[0], d[1]);
    };
    dpgen_test::check_adjoint(p);
    // the tangent's u is the kernel's, bit for bit
    const std::vector<double> u0 = dpgen_test::wavy(N, 0.4), rate = dpgen_test::wavy(N, 1.3);
    std::vector<double> u = u0, ut = u0, ud = dpgen_test::wavy(N, 2.0), rd(N, 0.0);
    Reaction1D{n, u.data(), rate.data()}.step(dt);
    Reaction1D_step_tangent(Reaction1D{n, ut.data(), rate.data()}, dt, ud.data(), rd.data());
    CHECK(dpgen_test::same_values(u, ut));
  }
}
