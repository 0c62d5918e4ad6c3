// init_then_acc_nests (tests/adversary/): see init_then_acc_nests.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "init_then_acc_nests_adjoint.hpp"
#include "init_then_acc_nests_tangent.hpp"
void init_then_acc_nests(const double*, const double*, double*, int n);
TEST_CASE("adversary: init_then_acc_nests") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { init_then_acc_nests(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { init_then_acc_nests_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { init_then_acc_nests_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      init_then_acc_nests_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
