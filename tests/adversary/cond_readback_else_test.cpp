// cond_readback_else (tests/adversary/): see cond_readback_else.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "cond_readback_else_adjoint.hpp"
#include "cond_readback_else_tangent.hpp"
void cond_readback_else(const double*, double*, int n);
TEST_CASE("adversary: cond_readback_else") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { cond_readback_else(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { cond_readback_else_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { cond_readback_else_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      cond_readback_else_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
