// clamp_minmax (tests/adversary/): see clamp_minmax.cpp; sizes n in {1, 2, 3, 6}.
#include "adv.hpp"
#include "clamp_minmax_adjoint.hpp"
#include "clamp_minmax_tangent.hpp"
void clamp_minmax(const double*, double*, int n);
TEST_CASE("adversary: clamp_minmax") {
  for (int n : {1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { clamp_minmax(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { clamp_minmax_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { clamp_minmax_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      clamp_minmax_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
