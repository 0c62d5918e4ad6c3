// burgers_step (tests/kernels/): nonlinear, periodic.
#include "support/adjoint_check.hpp"

#include "burgers_step_adjoint.hpp"
#include "burgers_step_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("burgers_step adjoint") {
  for (int n : {1, 2, 3, 5, 32}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { burgers_step(in[0], out[0], n, 0.1, 0.5, 0.05); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      burgers_step_adjoint(in[0], adj[0], seed[0], n, 0.1, 0.5, 0.05);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      burgers_step_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.1, 0.5, 0.05);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      burgers_step_tangent(in[0], dir[0], out[0], outd[0], n, 0.1, 0.5, 0.05);
    };
    dpgen_test::check_adjoint(p);
  }
}
