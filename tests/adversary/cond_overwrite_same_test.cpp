// cond_overwrite_same (tests/adversary/): see cond_overwrite_same.cpp; sizes n in {1, 2, 3, 8}.
#include "adv.hpp"
#include "cond_overwrite_same_adjoint.hpp"
#include "cond_overwrite_same_tangent.hpp"
void cond_overwrite_same(const double*, const double*, double*, int n);
TEST_CASE("adversary: cond_overwrite_same") {
  for (int n : {1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { cond_overwrite_same(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { cond_overwrite_same_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { cond_overwrite_same_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      cond_overwrite_same_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
