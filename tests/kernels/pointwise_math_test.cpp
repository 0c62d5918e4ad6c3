// pointwise_math (tests/kernels/): every supported math function.
#include "support/adjoint_check.hpp"

#include "pointwise_math_adjoint.hpp"
#include "pointwise_math_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("pointwise_math adjoint") {
  for (int n : {1, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { pointwise_math(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      pointwise_math_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      pointwise_math_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      pointwise_math_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
