#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_lw_param_shift_adjoint.hpp"
#include "r5_lw_param_shift_tangent.hpp"

DPGEN_KERNEL void r5_lw_param_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n, int s);
TEST_CASE("adversary: r5_lw_param_shift") {
  for (auto [n, s] : {std::pair{0, 1}, {1, 2}, {2, 2}, {1, 1}}) {
    CAPTURE(s);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n + 2)};
    p.forward = [&](auto in, auto out) { r5_lw_param_shift(in[0], out[0], n, s); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_lw_param_shift_adjoint(in[0], adj[0], seed[0], n, s); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_lw_param_shift_tangent(in[0], dir[0], out[0], outd[0], n, s); };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("adversary: r5_lw_param_shift overlapping throws") {
  // s = 0 (both stores on one element) and n > s (the stores meet across iterations): a run-time error
  std::vector<double> a(3, 0.5), a_adj(3, 0.0), K_seed(5, 1.0);
  CHECK_THROWS_AS(r5_lw_param_shift_adjoint(a.data(), a_adj.data(), K_seed.data(), 3, 0), std::invalid_argument);
  CHECK_THROWS_AS(r5_lw_param_shift_adjoint(a.data(), a_adj.data(), K_seed.data(), 3, 1), std::invalid_argument);
}
