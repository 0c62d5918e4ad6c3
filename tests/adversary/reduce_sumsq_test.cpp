#include "adv.hpp"
#include "reduce_sumsq_adjoint.hpp"
#include "reduce_sumsq_tangent.hpp"
void reduce_sumsq(const double* a, const double* b, double* loss, int n);
TEST_CASE("adversary: reduce_sumsq") {
  for (int n : {0, 1, 2, 3, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n), ADV_SZ(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { reduce_sumsq(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reduce_sumsq_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reduce_sumsq_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
