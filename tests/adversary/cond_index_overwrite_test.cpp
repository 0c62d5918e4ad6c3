// cond_index_overwrite (tests/adversary/): see cond_index_overwrite.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "cond_index_overwrite_adjoint.hpp"
#include "cond_index_overwrite_tangent.hpp"
void cond_index_overwrite(const double*, const double*, double*, int n);
TEST_CASE("adversary: cond_index_overwrite") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { cond_index_overwrite(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { cond_index_overwrite_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { cond_index_overwrite_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      cond_index_overwrite_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
