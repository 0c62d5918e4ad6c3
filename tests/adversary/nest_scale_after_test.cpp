// nest_scale_after (tests/adversary/): see nest_scale_after.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "nest_scale_after_adjoint.hpp"
#include "nest_scale_after_tangent.hpp"
void nest_scale_after(const double*, const double*, const double*, double*, int n);
TEST_CASE("adversary: nest_scale_after") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n * n),ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { nest_scale_after(in[0], in[1], in[2], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { nest_scale_after_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { nest_scale_after_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      nest_scale_after_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
