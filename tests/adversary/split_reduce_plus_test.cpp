// split_reduce_plus (tests/adversary/): see split_reduce_plus.cpp; sizes n in {1,2,5}.
#include "adv.hpp"
#include "split_reduce_plus_adjoint.hpp"
#include "split_reduce_plus_tangent.hpp"
void split_reduce_plus(const double*, double*, int n);
TEST_CASE("adversary: split_reduce_plus") {
  for (int n : {1,2,5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n > 1 ? n : 1)};
    p.out_sizes = {ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { split_reduce_plus(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { split_reduce_plus_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { split_reduce_plus_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      split_reduce_plus_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
