// nest_shift_acc (tests/adversary/): see nest_shift_acc.cpp; sizes n in {0, 1, 2, 4}.
#include "adv.hpp"
#include "nest_shift_acc_adjoint.hpp"
#include "nest_shift_acc_tangent.hpp"
void nest_shift_acc(const double*, const double*, double*, int n);
TEST_CASE("adversary: nest_shift_acc") {
  for (int n : {0, 1, 2, 4}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n * n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n + 1)};
    p.forward = [&](auto in, auto out) { nest_shift_acc(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { nest_shift_acc_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { nest_shift_acc_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      nest_shift_acc_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
