// step2_loop (tests/adversary/): see step2_loop.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "step2_loop_adjoint.hpp"
#include "step2_loop_tangent.hpp"
void step2_loop(const double*, double*, int n);
TEST_CASE("adversary: step2_loop") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { step2_loop(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { step2_loop_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { step2_loop_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      step2_loop_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
