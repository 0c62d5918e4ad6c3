// span_kernels (tests/kernels20/): std::span parameters; the adjoint and
// tangent take spans too (std::span<const double> for read-only arrays) and
// check that each adjoint span has its input's size.
#include "support/adjoint_check.hpp"

#include "span_kernels_adjoint.hpp"
#include "span_kernels_kernels.hpp"
#include "span_kernels_tangent.hpp"

#include <stdexcept>
#include <vector>

TEST_CASE("span_advect: std::span parameters") {
  const double dt = 0.3;
  for (size_t n : {1u, 2u, 7u}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      span_advect({in[0], n}, {in[1], n}, {out[0], n}, dt);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      span_advect_adjoint({in[0], n}, {adj[0], n}, {in[1], n}, {adj[1], n}, {seed[0], n}, dt);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      span_advect_tangent({in[0], n}, {dir[0], n}, {in[1], n}, {dir[1], n}, {out[0], n},
                          {od[0], n}, dt);
    };
    dpgen_test::check_adjoint(p);
  }
  std::vector<double> q(4, 1.0), qa(3, 0.0), s(4, 1.0);
  CHECK_THROWS_AS(span_advect_adjoint(q, qa, q, {}, s, dt), std::invalid_argument);
}
