// r3_cast_vals (tests/adversary/): see r3_cast_vals.cpp; sizes n in {1,2,3,6}.
#include "adv.hpp"
#include "r3_cast_vals_adjoint.hpp"
#include "r3_cast_vals_tangent.hpp"
void r3_cast_vals(const double*, double*, int n);
TEST_CASE("adversary: r3_cast_vals") {
  for (int n : {1,2,3,6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { r3_cast_vals(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_cast_vals_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_cast_vals_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      r3_cast_vals_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
