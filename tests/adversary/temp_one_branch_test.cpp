// temp_one_branch (tests/adversary/): see temp_one_branch.cpp; sizes n in {0, 1, 2, 5}.
#include "adv.hpp"
#include "temp_one_branch_adjoint.hpp"
#include "temp_one_branch_tangent.hpp"
void temp_one_branch(const double*, double*, int n);
TEST_CASE("adversary: temp_one_branch") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { temp_one_branch(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { temp_one_branch_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { temp_one_branch_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      temp_one_branch_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
