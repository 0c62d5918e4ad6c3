// reduce2d (tests/adversary/): see reduce2d.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "reduce2d_adjoint.hpp"
#include "reduce2d_tangent.hpp"
void reduce2d(const double*, double*, int n);
TEST_CASE("adversary: reduce2d") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n * n)};
    p.out_sizes = {ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { reduce2d(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reduce2d_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reduce2d_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      reduce2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
