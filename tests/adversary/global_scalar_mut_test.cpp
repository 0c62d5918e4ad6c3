// global_scalar_mut (tests/adversary/): see global_scalar_mut.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "global_scalar_mut_adjoint.hpp"
#include "global_scalar_mut_tangent.hpp"
void global_scalar_mut(const double*, double*, int n);
TEST_CASE("adversary: global_scalar_mut") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { global_scalar_mut(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { global_scalar_mut_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { global_scalar_mut_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      global_scalar_mut_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
