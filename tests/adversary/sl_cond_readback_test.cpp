// sl_cond_readback (tests/adversary/): see sl_cond_readback.cpp; sizes n in {2, 3, 5}.
#include "adv.hpp"
#include "sl_cond_readback_adjoint.hpp"
#include "sl_cond_readback_tangent.hpp"
void sl_cond_readback(const double*, double*, int n);
TEST_CASE("adversary: sl_cond_readback") {
  for (int n : {2, 3, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { sl_cond_readback(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { sl_cond_readback_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { sl_cond_readback_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      sl_cond_readback_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
