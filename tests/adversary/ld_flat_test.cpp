// ld_flat (tests/adversary/): leading dimension ld as a parameter. ld >= nx:
// correct adjoint, no exception; ld < nx with two or more rows: rows overlap,
// the adjoint must throw std::invalid_argument (not give a wrong gradient).
#include "adv.hpp"
#include "ld_flat_adjoint.hpp"
#include "ld_flat_tangent.hpp"
void ld_flat(const double* a, double* b, int ny, int nx, int ld);
TEST_CASE("adversary: ld_flat valid") {
  for (auto [ny, nx, ld] : {std::tuple{0, 0, 0}, {1, 1, 1}, {2, 3, 3}, {3, 2, 5}, {3, 4, 4}, {1, 3, 1}, {0, 3, 1}}) {
    CAPTURE(ny); CAPTURE(nx); CAPTURE(ld);
    dpgen_test::Problem<double> p;
    size_t sz = ny == 0 ? 0 : size_t((ny - 1) * ld + nx);
    p.in_sizes = {sz};
    p.out_sizes = {sz};
    p.forward = [&](auto in, auto out) { ld_flat(in[0], out[0], ny, nx, ld); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ld_flat_adjoint(in[0], adj[0], seed[0], ny, nx, ld); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ld_flat_tangent(in[0], dir[0], out[0], od[0], ny, nx, ld); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      ld_flat_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], ny, nx, ld);
    };
    bool threw = false;
    try { std::vector<double> x(64, 0.5), g(64, 0.0); ld_flat_adjoint(x.data(), g.data(), x.data(), ny, nx, ld); }
    catch (const std::invalid_argument& e) { threw = true; MESSAGE("spurious throw: " << e.what()); }
    if (ny > 1 || ld >= nx) CHECK_FALSE(threw);
    if (!threw) dpgen_test::check_adjoint(p);
  }
}
TEST_CASE("adversary: ld_flat throws when rows overlap") {
  std::vector<double> a(64, 0.5), adj(64, 0.0), seed(64, 1.0);
  CHECK_THROWS_AS(ld_flat_adjoint(a.data(), adj.data(), seed.data(), 3, 4, 3), std::invalid_argument);
  CHECK_THROWS_AS(ld_flat_adjoint(a.data(), adj.data(), seed.data(), 2, 4, 0), std::invalid_argument);
  CHECK_THROWS_AS(ld_flat_adjoint(a.data(), adj.data(), seed.data(), 2, 4, -1), std::invalid_argument);
}
