// ptr_param_incr (tests/adversary/): see ptr_param_incr.cpp; sizes n in {1, 2, 5}.
#include "adv.hpp"
#include "ptr_param_incr_adjoint.hpp"
#include "ptr_param_incr_tangent.hpp"
void ptr_param_incr(const double*, double*, int n);
TEST_CASE("adversary: ptr_param_incr") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n + 1)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { ptr_param_incr(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ptr_param_incr_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ptr_param_incr_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      ptr_param_incr_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
