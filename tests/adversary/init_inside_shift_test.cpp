// init_inside_shift (tests/adversary/): see init_inside_shift.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "init_inside_shift_adjoint.hpp"
#include "init_inside_shift_tangent.hpp"
void init_inside_shift(const double*, double*, int n);
TEST_CASE("adversary: init_inside_shift") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n * n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { init_inside_shift(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { init_inside_shift_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { init_inside_shift_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      init_inside_shift_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
