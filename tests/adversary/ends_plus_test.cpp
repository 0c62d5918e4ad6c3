// ends_plus (tests/adversary/): see ends_plus.cpp; sizes n in {1, 2, 3}.
#include "adv.hpp"
#include "ends_plus_adjoint.hpp"
#include "ends_plus_tangent.hpp"
void ends_plus(const double*, double*, int n);
TEST_CASE("adversary: ends_plus") {
  for (int n : {1, 2, 3}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { ends_plus(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ends_plus_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ends_plus_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      ends_plus_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
