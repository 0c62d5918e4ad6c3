// reduce_sqrt (tests/adversary/): see reduce_sqrt.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "reduce_sqrt_adjoint.hpp"
#include "reduce_sqrt_tangent.hpp"
void reduce_sqrt(const double*, double*, int n);
TEST_CASE("adversary: reduce_sqrt") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { reduce_sqrt(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reduce_sqrt_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reduce_sqrt_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      reduce_sqrt_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
