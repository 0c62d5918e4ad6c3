// helper_int_index (tests/adversary/): see helper_int_index.cpp; sizes n in {1, 2, 3, 6}.
#include "adv.hpp"
#include "helper_int_index_adjoint.hpp"
#include "helper_int_index_tangent.hpp"
void helper_int_index(const double*, double*, int n);
TEST_CASE("adversary: helper_int_index") {
  for (int n : {1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { helper_int_index(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { helper_int_index_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { helper_int_index_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      helper_int_index_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
