// workarr_out (tests/adversary/): see workarr_out.cpp; sizes n in {0, 1, 3, 6}.
#include "adv.hpp"
#include "workarr_out_adjoint.hpp"
#include "workarr_out_tangent.hpp"
void workarr_out(const double*, double*, double*, int n);
TEST_CASE("adversary: workarr_out") {
  for (int n : {0, 1, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { workarr_out(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { workarr_out_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { workarr_out_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      workarr_out_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
