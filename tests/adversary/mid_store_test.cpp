// mid_store (tests/adversary/): see mid_store.cpp; sizes n in {2, 3, 4, 5}.
#include "adv.hpp"
#include "mid_store_adjoint.hpp"
#include "mid_store_tangent.hpp"
void mid_store(const double*, double*, int n);
TEST_CASE("adversary: mid_store") {
  for (int n : {2, 3, 4, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { mid_store(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { mid_store_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { mid_store_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mid_store_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
