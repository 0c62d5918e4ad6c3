// pdv_ptrscalars (tests/styles/): scalars by pointer, bounds x_min..x_max;
// nonlinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "pdv_ptrscalars_adjoint.hpp"
#include "pdv_ptrscalars_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void pdv_ptrscalars(const int* xmin, const int* xmax, const double* dt,
                                 DPGEN_IN const double* density, DPGEN_IN const double* pressure,
                                 DPGEN_IN const double* volume, DPGEN_IN const double* xvel,
                                 DPGEN_OUT double* energy_change);

TEST_CASE("styles: pdv_ptrscalars") {
  for (auto [x_min, x_max] : {std::tuple{1, 0}, {1, 1}, {0, 2}, {1, 6}, {3, 10}}) {
    CAPTURE(x_min);
    CAPTURE(x_max);
    size_t n = size_t(x_max + 2);
    const double dt = 0.1;
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n, n, n};
    p.out_sizes = {n};
    p.in_ranges = {{1.0, 2.0}, {0.5, 1.5}, {1.0, 2.0}, {-1.0, 1.0}};
    p.forward = [&](auto in, auto out) {
      pdv_ptrscalars(&x_min, &x_max, &dt, in[0], in[1], in[2], in[3], out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      pdv_ptrscalars_adjoint(&x_min, &x_max, &dt, in[0], adj[0], in[1], adj[1], in[2], adj[2],
                             in[3], adj[3], seed[0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      pdv_ptrscalars_tangent(&x_min, &x_max, &dt, in[0], dir[0], in[1], dir[1], in[2], dir[2], in[3], dir[3], out[0], outd[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
