// r3_uns_cond_im1 (tests/adversary/): see r3_uns_cond_im1.cpp; sizes n in {0,1,2,3,6}.
#include "adv.hpp"
#include "r3_uns_cond_im1_adjoint.hpp"
#include "r3_uns_cond_im1_tangent.hpp"
void r3_uns_cond_im1(const double*, double*, unsigned n);
TEST_CASE("adversary: r3_uns_cond_im1") {
  for (unsigned n : {0,1,2,3,6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { r3_uns_cond_im1(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_uns_cond_im1_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_uns_cond_im1_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      r3_uns_cond_im1_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
