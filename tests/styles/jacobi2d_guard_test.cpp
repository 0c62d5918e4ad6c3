// jacobi2d_guard (tests/styles/): out-of-place Jacobi with a leading guard;
// linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "jacobi2d_guard_adjoint.hpp"
#include "jacobi2d_guard_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void jacobi2d_guard(DPGEN_IN const double* x, DPGEN_IN const double* b,
                                 DPGEN_OUT double* x_new, int nx, int ny, double h2,
                                 double omega);

TEST_CASE("styles: jacobi2d_guard") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 5}, {3, 3}, {4, 6}, {8, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { jacobi2d_guard(in[0], in[1], out[0], nx, ny, 0.01, 0.8); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      jacobi2d_guard_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.01, 0.8);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      jacobi2d_guard_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.01, 0.8);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      jacobi2d_guard_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, 0.01, 0.8);
    };
    dpgen_test::check_adjoint(p);
  }
}
