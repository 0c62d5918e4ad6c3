// pow_sqrt (tests/adversary/): pow with an active base and exponent, an
// integer exponent, sqrt, exp of tanh; a in [0.5, 2] so pow is smooth.
#include "adv.hpp"
#include "pow_sqrt_adjoint.hpp"
#include "pow_sqrt_tangent.hpp"
void pow_sqrt(const double* a, const double* b, double* out, int n);
TEST_CASE("adversary: pow_sqrt") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n), ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}};
    p.forward = [&](auto in, auto out) { pow_sqrt(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { pow_sqrt_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { pow_sqrt_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
