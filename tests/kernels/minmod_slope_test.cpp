// minmod_slope (tests/kernels/): data-dependent if/else on locals.
#include "support/adjoint_check.hpp"

#include "minmod_slope_adjoint.hpp"
#include "minmod_slope_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("minmod_slope adjoint") {
  for (int n : {1, 3, 4, 30}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { minmod_slope(in[0], out[0], n, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      minmod_slope_adjoint(in[0], adj[0], seed[0], n, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      minmod_slope_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      minmod_slope_tangent(in[0], dir[0], out[0], outd[0], n, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}
