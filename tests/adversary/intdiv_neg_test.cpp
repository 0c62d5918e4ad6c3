// intdiv_neg (tests/adversary/): see intdiv_neg.cpp; sizes n in {2, 3, 4, 7}.
#include "adv.hpp"
#include "intdiv_neg_adjoint.hpp"
#include "intdiv_neg_tangent.hpp"
void intdiv_neg(const double*, double*, int n);
TEST_CASE("adversary: intdiv_neg") {
  for (int n : {2, 3, 4, 7}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { intdiv_neg(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { intdiv_neg_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { intdiv_neg_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      intdiv_neg_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
