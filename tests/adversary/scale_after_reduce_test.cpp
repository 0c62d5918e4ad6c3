// scale_after_reduce (tests/adversary/): see scale_after_reduce.cpp; sizes n in {0, 1, 2, 5}.
#include "adv.hpp"
#include "scale_after_reduce_adjoint.hpp"
#include "scale_after_reduce_tangent.hpp"
void scale_after_reduce(const double*, double*, int n);
TEST_CASE("adversary: scale_after_reduce") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(1)};
    p.forward = [&](auto in, auto out) { scale_after_reduce(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { scale_after_reduce_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { scale_after_reduce_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      scale_after_reduce_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
