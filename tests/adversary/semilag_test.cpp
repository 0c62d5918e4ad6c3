// semilag (tests/adversary/): semi-Lagrangian advection, data-dependent
// periodic index (scatter adjoint); |dt v| < 1 keeps the wrap one-sided.
#include "adv.hpp"
#include "semilag_adjoint.hpp"
#include "semilag_tangent.hpp"
void semilag(const double* q, const double* v, double* out, int n, double dt);
TEST_CASE("adversary: semilag") {
  for (int n : {1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n), ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.in_ranges = {{-1.0, 1.0}, {0.05, 0.95}};
    p.forward = [&](auto in, auto out) { semilag(in[0], in[1], out[0], n, 0.9); };
    p.adjoint = [&](auto in, auto adj, auto seed) { semilag_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.9); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { semilag_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n, 0.9); };
    dpgen_test::check_adjoint(p);
  }
}
