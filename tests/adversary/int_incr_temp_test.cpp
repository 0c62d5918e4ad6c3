// int_incr_temp (tests/adversary/): see int_incr_temp.cpp; sizes n in {0, 1, 2, 5}.
#include "adv.hpp"
#include "int_incr_temp_adjoint.hpp"
#include "int_incr_temp_tangent.hpp"
void int_incr_temp(const double*, double*, int n);
TEST_CASE("adversary: int_incr_temp") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { int_incr_temp(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { int_incr_temp_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { int_incr_temp_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      int_incr_temp_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
