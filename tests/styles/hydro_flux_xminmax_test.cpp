// hydro_flux_xminmax (tests/styles/): parameter lower bounds with a leading
// dimension, scalars by pointer; bilinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "hydro_flux_xminmax_adjoint.hpp"
#include "hydro_flux_xminmax_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void hydro_flux_xminmax(const int* xmin, const int* xmax, const int* ymin,
                                     const int* ymax, const double* dt,
                                     DPGEN_IN const double* xarea, DPGEN_IN const double* xvel0,
                                     DPGEN_IN const double* xvel1, DPGEN_OUT double* vol_flux_x);

TEST_CASE("styles: hydro_flux_xminmax") {
  for (auto [x_min, x_max, y_min, y_max] :
       {std::tuple{1, 1, 1, 1}, {1, 2, 1, 3}, {1, 5, 1, 4}, {0, 3, 2, 4}, {3, 6, 1, 2}}) {
    CAPTURE(x_min);
    CAPTURE(x_max);
    CAPTURE(y_min);
    CAPTURE(y_max);
    size_t n = size_t((x_max - x_min + 5) * (y_max - y_min + 5));
    const double dt = 0.04;
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      hydro_flux_xminmax(&x_min, &x_max, &y_min, &y_max, &dt, in[0], in[1], in[2], out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      hydro_flux_xminmax_adjoint(&x_min, &x_max, &y_min, &y_max, &dt, in[0], adj[0], in[1],
                                 adj[1], in[2], adj[2], seed[0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      hydro_flux_xminmax_tangent(&x_min, &x_max, &y_min, &y_max, &dt, in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
