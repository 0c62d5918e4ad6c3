// diffusion2d_bounds_params (tests/styles/): lower bounds as parameters plus a
// leading dimension; linear. Halo width 1, sometimes a wider ld than needed.
#include "support/adjoint_check.hpp"

#include "diffusion2d_bounds_params_adjoint.hpp"
#include "diffusion2d_bounds_params_tangent.hpp"
#include "dpgen/annotate.hpp"

#include <tuple>

DPGEN_KERNEL void diffusion2d_bounds_params(DPGEN_IN const double* u, DPGEN_OUT double* un,
                                            int x_min, int x_max, int y_min, int y_max, int ld,
                                            double nu);

TEST_CASE("styles: diffusion2d_bounds_params") {
  // x_min, x_max, y_min, y_max, ld, rows
  for (auto [x0, x1, y0, y1, ld, rows] : {std::tuple{1, 1, 1, 1, 3, 3}, {1, 0, 1, 2, 3, 4},
                                          {1, 4, 1, 3, 6, 5}, {2, 4, 3, 5, 9, 7},
                                          {1, 5, 1, 1, 7, 3}}) {
    CAPTURE(x0);
    CAPTURE(x1);
    CAPTURE(y0);
    CAPTURE(y1);
    CAPTURE(ld);
    size_t n = size_t(ld * rows);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      diffusion2d_bounds_params(in[0], out[0], x0, x1, y0, y1, ld, 0.2);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      diffusion2d_bounds_params_adjoint(in[0], adj[0], seed[0], x0, x1, y0, y1, ld, 0.2);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      diffusion2d_bounds_params_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], x0, x1, y0, y1, ld, 0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      diffusion2d_bounds_params_tangent(in[0], dir[0], out[0], outd[0], x0, x1, y0, y1, ld, 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}
