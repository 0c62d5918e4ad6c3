// flux_calc_idx_macro (tests/styles/): indices through a macro with the
// bounds folded in, sizes by pointer (issue 20, defect 5).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "flux_calc_idx_macro_adjoint.hpp"
#include "flux_calc_idx_macro_kernels.hpp"
#include "flux_calc_idx_macro_tangent.hpp"

#include <tuple>

TEST_CASE("styles: flux_calc_idx_macro") {
  for (auto [x_min, x_max, y_min, y_max] :
       {std::tuple{0, 0, 0, 0}, {1, 3, 1, 2}, {0, 6, 2, 5}, {2, 9, 0, 4}}) {
    CAPTURE(x_max);
    CAPTURE(y_max);
    const int xmin = x_min, xmax = x_max, ymin = y_min, ymax = y_max;
    const double dt = 0.37;
    const size_t size = size_t(x_max + 5) * size_t(y_max - y_min + 6);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size, size, size};
    p.out_sizes = {size};
    p.forward = [&](auto in, auto out) {
      flux_calc_idx_macro(&xmin, &xmax, &ymin, &ymax, &dt, in[0], in[1], in[2], out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flux_calc_idx_macro_adjoint(&xmin, &xmax, &ymin, &ymax, &dt, in[0], adj[0], in[1], adj[1],
                                  in[2], adj[2], seed[0]);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      flux_calc_idx_macro_tangent(&xmin, &xmax, &ymin, &ymax, &dt, in[0], d[0], in[1], d[1], in[2],
                                  d[2], out[0], dout[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
