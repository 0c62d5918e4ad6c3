// reduce_then_plus (tests/adversary/): see reduce_then_plus.cpp; sizes n in {1, 2, 5}.
#include "adv.hpp"
#include "reduce_then_plus_adjoint.hpp"
#include "reduce_then_plus_tangent.hpp"
void reduce_then_plus(const double*, double*, int n);
TEST_CASE("adversary: reduce_then_plus") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { reduce_then_plus(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reduce_then_plus_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reduce_then_plus_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      reduce_then_plus_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
