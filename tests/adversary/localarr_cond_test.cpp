// localarr_cond (tests/adversary/): see localarr_cond.cpp; sizes n in {0, 1, 3, 8}.
#include "adv.hpp"
#include "localarr_cond_adjoint.hpp"
#include "localarr_cond_tangent.hpp"
void localarr_cond(const double*, const double*, double*, int n);
TEST_CASE("adversary: localarr_cond") {
  for (int n : {0, 1, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { localarr_cond(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { localarr_cond_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { localarr_cond_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      localarr_cond_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
