#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include <vector>
#include "dpgen/annotate.hpp"
#include "a08_straight_k_before_adjoint.hpp"
#include "a08_straight_k_before_tangent.hpp"

DPGEN_KERNEL void a08_straight_k_before(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int k);
TEST_CASE("adversary: a08_straight_k_before") {
  for (int n : {1, 2, 3, 5}) for (int k = 0; k < n; ++k) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a08_straight_k_before(in[0], out[0], n, k); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a08_straight_k_before_adjoint(in[0], adj[0], seed[0], n, k); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a08_straight_k_before_tangent(in[0], dir[0], out[0], outd[0], n, k); };
    if (k >= 1 && k <= n - 2) {
      // u[k] and the loop's u[i] overlap: an overwrite across statements is
      // outside the subset; the adjoint's run-time check must say so.
      std::vector<double> a(n, 1.0), aa(n, 0.0), s(n, 1.0);
      CHECK_THROWS_AS(a08_straight_k_before_adjoint(a.data(), aa.data(), s.data(), n, k), std::invalid_argument);
      continue;
    }
    dpgen_test::check_adjoint(p);
  }
}
