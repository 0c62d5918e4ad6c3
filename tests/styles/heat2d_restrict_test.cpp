// heat2d_restrict (tests/styles/): __restrict pointers; bilinear. The
// adjoint's own pointers may or may not be __restrict: the call is the same.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat2d_restrict_adjoint.hpp"
#include "heat2d_restrict_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void heat2d_restrict(DPGEN_IN const double* __restrict t,
                                  DPGEN_IN const double* __restrict kappa,
                                  DPGEN_OUT double* __restrict t_new, int nx, int ny,
                                  double dt_h2);

TEST_CASE("styles: heat2d_restrict") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 2}, {3, 3}, {5, 4}, {8, 6}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.in_ranges = {{-1.0, 1.0}, {0.5, 2.0}};
    p.forward = [&](auto in, auto out) { heat2d_restrict(in[0], in[1], out[0], nx, ny, 0.1); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat2d_restrict_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.1);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat2d_restrict_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.1);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat2d_restrict_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, 0.1);
    };
    dpgen_test::check_adjoint(p);
  }
}
