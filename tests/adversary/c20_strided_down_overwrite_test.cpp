// c20_strided_down_overwrite (tests/adversary/): see c20_strided_down_overwrite.cpp;
// sizes n in {0, ..., 9} (even and odd: the last iteration stops at 2 or 3).
#include "adv.hpp"
#include "c20_strided_down_overwrite_adjoint.hpp"
#include "c20_strided_down_overwrite_tangent.hpp"
void c20_strided_down_overwrite(const double*, double*, int n);
void c20_strided_up_overwrite(const double*, double*, int n);
TEST_CASE("adversary: c20_strided_down_overwrite") {
  for (int n = 0; n < 10; ++n) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { c20_strided_down_overwrite(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      c20_strided_down_overwrite_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      c20_strided_down_overwrite_tangent(in[0], dir[0], out[0], od[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      c20_strided_down_overwrite_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0],
                                                 n);
    };
    dpgen_test::check_adjoint(p);
    p.forward = [&](auto in, auto out) { c20_strided_up_overwrite(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      c20_strided_up_overwrite_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      c20_strided_up_overwrite_tangent(in[0], dir[0], out[0], od[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      c20_strided_up_overwrite_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0],
                                               n);
    };
    dpgen_test::check_adjoint(p);
  }
}
