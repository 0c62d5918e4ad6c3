// temp_reduce_inner (tests/adversary/): see temp_reduce_inner.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "temp_reduce_inner_adjoint.hpp"
#include "temp_reduce_inner_tangent.hpp"
void temp_reduce_inner(const double*, const double*, double*, int n);
TEST_CASE("adversary: temp_reduce_inner") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n * n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { temp_reduce_inner(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { temp_reduce_inner_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { temp_reduce_inner_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      temp_reduce_inner_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
