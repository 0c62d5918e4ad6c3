// ends_then_loop_all (tests/adversary/): see ends_then_loop_all.cpp; sizes n in {1, 2, 3, 5}.
#include "adv.hpp"
#include "ends_then_loop_all_adjoint.hpp"
#include "ends_then_loop_all_tangent.hpp"
void ends_then_loop_all(const double*, double*, int n);
TEST_CASE("adversary: ends_then_loop_all") {
  for (int n : {1, 2, 3, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { ends_then_loop_all(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ends_then_loop_all_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ends_then_loop_all_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      ends_then_loop_all_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
