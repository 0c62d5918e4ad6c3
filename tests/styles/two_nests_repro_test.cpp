// two_nests_repro (tests/styles/): the reproducer; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "two_nests_repro_adjoint.hpp"
#include "two_nests_repro_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void two_nests_repro(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                  DPGEN_OUT double* x, DPGEN_OUT double* y, int m, int n);

TEST_CASE("styles: two_nests_repro") {
  for (auto [m, n] : {std::tuple{1, 1}, {1, 0}, {2, 3}, {4, 2}, {3, 6}}) {
    CAPTURE(m);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(m * (n + 2)), size_t((m + 1) * (n + 2))};
    p.out_sizes = {size_t(m * (n + 2)), size_t((m + 1) * (n + 2))};
    p.linear = true;
    p.forward = [&](auto in, auto out) { two_nests_repro(in[0], in[1], out[0], out[1], m, n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      two_nests_repro_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], m, n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      two_nests_repro_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], seed[1], out_n[1], m, n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      two_nests_repro_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], out[1], outd[1], m, n);
    };
    dpgen_test::check_adjoint(p);
  }
}
