// countdown_unsigned (tests/adversary/): see countdown_unsigned.cpp; sizes n in {0u, 1u, 2u, 5u}.
#include "adv.hpp"
#include "countdown_unsigned_adjoint.hpp"
#include "countdown_unsigned_tangent.hpp"
void countdown_unsigned(const double*, double*, unsigned n);
TEST_CASE("adversary: countdown_unsigned") {
  for (unsigned n : {0u, 1u, 2u, 5u}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { countdown_unsigned(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { countdown_unsigned_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { countdown_unsigned_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      countdown_unsigned_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
