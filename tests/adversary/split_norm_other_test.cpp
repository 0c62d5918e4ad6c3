// split_norm_other (tests/adversary/): see split_norm_other.cpp; sizes n in {0,1,2,5}.
#include "adv.hpp"
#include "split_norm_other_adjoint.hpp"
#include "split_norm_other_tangent.hpp"
void split_norm_other(const double*, double*, double*, int n);
TEST_CASE("adversary: split_norm_other") {
  for (int n : {0,1,2,5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n > 1 ? n : 1)};
    p.out_sizes = {ADV_SZ(1),ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { split_norm_other(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { split_norm_other_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { split_norm_other_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      split_norm_other_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
