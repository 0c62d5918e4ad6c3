// strided (tests/kernels/): stride-2, reversed and non-affine reads.
#include "support/adjoint_check.hpp"

#include "strided_adjoint.hpp"
#include "test_kernels.hpp"

TEST_CASE("strided adjoint") {
  for (int n : {1, 2, 5, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(2 * n)};
    p.out_sizes = {size_t(2 * n)};
    p.forward = [&](auto in, auto out) { strided(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { strided_adjoint(in[0], adj[0], seed[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
