#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_lw_two_loops_overwrite_adjoint.hpp"
#include "r5_lw_two_loops_overwrite_tangent.hpp"

DPGEN_KERNEL void r5_lw_two_loops_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* K, int n);
TEST_CASE("adversary: r5_lw_two_loops_overwrite") {
  for (int n : {0, 1}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n + 1)};
    p.forward = [&](auto in, auto out) { r5_lw_two_loops_overwrite(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_lw_two_loops_overwrite_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_lw_two_loops_overwrite_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("adversary: r5_lw_two_loops_overwrite n = 2 throws") {
  std::vector<double> a(2, 0.5), a_adj(2, 0.0), K_seed(3, 1.0);
  CHECK_THROWS_AS(r5_lw_two_loops_overwrite_adjoint(a.data(), a_adj.data(), K_seed.data(), 2), std::invalid_argument);
}
