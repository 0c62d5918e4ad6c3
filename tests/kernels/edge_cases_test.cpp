// edge_cases (tests/kernels/): early return, reverse loop, bool local, fmin/fmax.
#include "support/adjoint_check.hpp"

#include "edge_cases_adjoint.hpp"
#include "edge_cases_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("edge_cases adjoint") {
  for (int n : {1, 2, 3, 6, 25}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), 2};
    p.forward = [&](auto in, auto out) { edge_cases(in[0], in[1], out[0], out[1], n, 0.1); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      edge_cases_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], n, 0.1);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      edge_cases_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], seed[1], out_n[1], n, 0.1);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      edge_cases_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], out[1], outd[1], n, 0.1);
    };
    dpgen_test::check_adjoint(p);
  }
}
