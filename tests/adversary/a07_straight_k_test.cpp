#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a07_straight_k_adjoint.hpp"
#include "a07_straight_k_tangent.hpp"

DPGEN_KERNEL void a07_straight_k(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int k);
TEST_CASE("adversary: a07_straight_k") {
  for (int n : {1, 2, 3, 5}) for (int k = 0; k < n; ++k) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a07_straight_k(in[0], out[0], n, k); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a07_straight_k_adjoint(in[0], adj[0], seed[0], n, k); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a07_straight_k_tangent(in[0], dir[0], out[0], outd[0], n, k); };
    dpgen_test::check_adjoint(p);
  }
}
