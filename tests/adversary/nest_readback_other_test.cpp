// nest_readback_other (tests/adversary/): see nest_readback_other.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "nest_readback_other_adjoint.hpp"
#include "nest_readback_other_tangent.hpp"
void nest_readback_other(const double*, double*, double*, int n);
TEST_CASE("adversary: nest_readback_other") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { nest_readback_other(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { nest_readback_other_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { nest_readback_other_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      nest_readback_other_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
