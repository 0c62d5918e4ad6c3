#include "adv.hpp"
#include "reduce_ptr_star_adjoint.hpp"
#include "reduce_ptr_star_tangent.hpp"
void reduce_ptr_star(const double* a, double* loss, int n);
TEST_CASE("adversary: reduce_ptr_star") {
  for (int n : {0, 1, 2, 3, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { reduce_ptr_star(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reduce_ptr_star_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reduce_ptr_star_tangent(in[0], dir[0], out[0], od[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
