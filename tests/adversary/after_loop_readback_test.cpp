// after_loop_readback (tests/adversary/): see after_loop_readback.cpp; sizes n in {1, 2, 5}.
#include "adv.hpp"
#include "after_loop_readback_adjoint.hpp"
#include "after_loop_readback_tangent.hpp"
void after_loop_readback(const double*, double*, int n);
TEST_CASE("adversary: after_loop_readback") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { after_loop_readback(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { after_loop_readback_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { after_loop_readback_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      after_loop_readback_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
