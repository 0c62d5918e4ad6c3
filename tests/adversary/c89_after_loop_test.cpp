// c89_after_loop (tests/adversary/): see c89_after_loop.cpp; sizes n in {1, 2, 5}.
#include "adv.hpp"
#include "c89_after_loop_adjoint.hpp"
#include "c89_after_loop_tangent.hpp"
void c89_after_loop(const double*, double*, int n);
TEST_CASE("adversary: c89_after_loop") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { c89_after_loop(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { c89_after_loop_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { c89_after_loop_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      c89_after_loop_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
