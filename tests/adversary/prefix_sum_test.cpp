// prefix_sum (tests/adversary/): see prefix_sum.cpp; sizes n in {1, 2, 3, 8}.
#include "adv.hpp"
#include "prefix_sum_adjoint.hpp"
#include "prefix_sum_tangent.hpp"
void prefix_sum(const double*, double*, int n);
TEST_CASE("adversary: prefix_sum") {
  for (int n : {1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { prefix_sum(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { prefix_sum_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { prefix_sum_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      prefix_sum_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
