// reduce_product (tests/adversary/): see reduce_product.cpp; sizes n in {0, 1, 2, 5}.
#include "adv.hpp"
#include "reduce_product_adjoint.hpp"
#include "reduce_product_tangent.hpp"
void reduce_product(const double*, double*, int n);
TEST_CASE("adversary: reduce_product") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { reduce_product(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reduce_product_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reduce_product_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      reduce_product_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
