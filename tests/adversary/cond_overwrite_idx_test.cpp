// cond_overwrite_idx (tests/adversary/): see cond_overwrite_idx.cpp; sizes n in {1, 2, 3, 8}.
#include "adv.hpp"
#include "cond_overwrite_idx_adjoint.hpp"
#include "cond_overwrite_idx_tangent.hpp"
void cond_overwrite_idx(const double*, double*, int n);
TEST_CASE("adversary: cond_overwrite_idx") {
  for (int n : {1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { cond_overwrite_idx(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { cond_overwrite_idx_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { cond_overwrite_idx_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      cond_overwrite_idx_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
