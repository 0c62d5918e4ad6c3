// helper_param_mod (tests/adversary/): see helper_param_mod.cpp; sizes n in {0, 1, 3}.
#include "adv.hpp"
#include "helper_param_mod_adjoint.hpp"
#include "helper_param_mod_tangent.hpp"
void helper_param_mod(const double*, const double*, double*, int n);
TEST_CASE("adversary: helper_param_mod") {
  for (int n : {0, 1, 3}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { helper_param_mod(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { helper_param_mod_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { helper_param_mod_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      helper_param_mod_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
