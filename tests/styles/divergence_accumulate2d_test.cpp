// divergence_accumulate2d (tests/styles/): += into an output, staggered
// grid, i++. Same in/out assumption as rhs_accumulate_test.cpp.
#include "support/adjoint_check.hpp"

#include "divergence_accumulate2d_adjoint.hpp"
#include "divergence_accumulate2d_tangent.hpp"
#include "dpgen/annotate.hpp"

#include <tuple>

DPGEN_KERNEL void divergence_accumulate2d(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                          DPGEN_IN const double* phi, DPGEN_OUT double* div,
                                          int nx, int ny, double inv_h);

TEST_CASE("styles: divergence_accumulate2d") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 1}, {3, 4}, {6, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {Y * (X + 1), (Y + 1) * X, X * Y};
    p.out_sizes = {X * Y};
    p.forward = [&](auto in, auto out) {
      divergence_accumulate2d(in[0], in[1], in[2], out[0], nx, ny, 2.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      divergence_accumulate2d_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], nx,
                                      ny, 2.0);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      divergence_accumulate2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], seed[0], out_n[0], nx, ny, 2.0);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      divergence_accumulate2d_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], nx, ny, 2.0);
    };
    dpgen_test::check_adjoint(p);
  }
}
