// two_loops_minimal (tests/styles/): two loops, one input, different bounds;
// linear. Plus the hand-computed adjoint for n = 3: a_adj = x_adj + y_adj on
// cells 1..2, x_adj only on cell 0.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "two_loops_minimal_adjoint.hpp"
#include "two_loops_minimal_tangent.hpp"

DPGEN_KERNEL void two_loops_minimal(DPGEN_IN const double* a, DPGEN_OUT double* x,
                                    DPGEN_OUT double* y, int n);

TEST_CASE("styles: two_loops_minimal") {
  for (int n : {1, 2, 3, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { two_loops_minimal(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      two_loops_minimal_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      two_loops_minimal_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      two_loops_minimal_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
  double a[3] = {1, 2, 3}, a_adj[3] = {0, 0, 0}, x_adj[3] = {0, 0, 0}, y_adj[3] = {1, 1, 1};
  two_loops_minimal_adjoint(a, a_adj, x_adj, y_adj, 3);
  CHECK(a_adj[0] == 0.0);
  CHECK(a_adj[1] == 1.0);
  CHECK(a_adj[2] == 1.0);
}
