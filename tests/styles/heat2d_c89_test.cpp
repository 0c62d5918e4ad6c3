// heat2d_c89 (tests/styles/): C89 counters + omp pragma; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat2d_c89_adjoint.hpp"
#include "heat2d_c89_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void heat2d_c89(DPGEN_IN const double* t, DPGEN_OUT double* t_new, int nx, int ny,
                             double rx, double ry);

TEST_CASE("styles: heat2d_c89") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 3}, {3, 3}, {5, 4}, {9, 7}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nx * ny)};
    p.out_sizes = {size_t(nx * ny)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { heat2d_c89(in[0], out[0], nx, ny, 0.2, 0.15); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat2d_c89_adjoint(in[0], adj[0], seed[0], nx, ny, 0.2, 0.15);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat2d_c89_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, 0.2, 0.15);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat2d_c89_tangent(in[0], dir[0], out[0], outd[0], nx, ny, 0.2, 0.15);
    };
    dpgen_test::check_adjoint(p);
  }
}
