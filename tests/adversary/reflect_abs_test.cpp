// reflect_abs (tests/adversary/): see reflect_abs.cpp; sizes n in {2, 3, 6}.
#include "adv.hpp"
#include "reflect_abs_adjoint.hpp"
#include "reflect_abs_tangent.hpp"
void reflect_abs(const double*, double*, int n);
TEST_CASE("adversary: reflect_abs") {
  for (int n : {2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { reflect_abs(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reflect_abs_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { reflect_abs_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      reflect_abs_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
