// riemann_outparams (tests/kernels/riemann_outparams.c): a C kernel whose
// flux helper returns two values through pointers (`&a, &b`), a helper called
// from a helper, fluxes in work arrays read by the update loop.
#include "support/adjoint_check.hpp"

#include "riemann_outparams_adjoint.hpp"
#include "riemann_outparams_kernels.hpp"
#include "riemann_outparams_tangent.hpp"

TEST_CASE("riemann_outparams adjoint (void helper with pointer out-parameters, C)") {
  const double g = 9.81, dtdx = 0.05;
  for (int n : {1, 2, 3, 8, 17}) {
    CAPTURE(n);
    const size_t m = size_t(n > 1 ? n - 1 : 0), nn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {nn, nn};
    p.in_ranges = {{1.0, 2.0}, {-0.5, 0.5}}; // depths positive
    p.out_sizes = {m, m, nn, nn};
    p.forward = [&](auto in, auto out) {
      riemann_outparams(in[0], in[1], out[0], out[1], out[2], out[3], n, g, dtdx);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      riemann_outparams_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], seed[2], seed[3],
                                n, g, dtdx);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      riemann_outparams_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], out[1], od[1],
                                out[2], od[2], out[3], od[3], n, g, dtdx);
    };
    dpgen_test::check_adjoint(p);
  }
}
