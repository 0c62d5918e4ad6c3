// upwind_step (kernels/): signature rule, adjoint checks on several sizes.
#include "support/adjoint_check.hpp"

#include "kernels.hpp"
#include "upwind_step_adjoint.hpp"
#include "upwind_step_tangent.hpp"

#include <type_traits>

using dpgen_test::Problem;

// DPGEN_IN d, u -> (d, d_adj, u, u_adj); DPGEN_OUT d_next -> d_next_adj.
static_assert(std::is_same_v<decltype(&upwind_step_adjoint),
                             void (*)(const double*, double*, const double*, double*,
                                      const double*, int, double, double)>);

TEST_CASE("upwind_step adjoint") {
  for (int n : {1, 2, 3, 4, 7, 64}) {
    CAPTURE(n);
    const double dt = 0.3, dx = 0.7;
    Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { upwind_step(in[0], in[1], out[0], n, dt, dx); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      upwind_step_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, dt, dx);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      upwind_step_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, dt, dx);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      upwind_step_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, dt, dx);
    };
    dpgen_test::check_adjoint(p);
  }
}
