#include "adv.hpp"
#include "countdown_int_adjoint.hpp"
#include "countdown_int_tangent.hpp"
void countdown_int(const double* a, double* out, int n);
TEST_CASE("adversary: countdown_int") {
  for (int n : {0, 1, 2, 3, 4, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { countdown_int(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { countdown_int_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { countdown_int_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      countdown_int_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
