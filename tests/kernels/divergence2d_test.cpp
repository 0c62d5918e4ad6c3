// divergence2d (kernels/): signature rule, adjoint checks (linear).
#include "support/adjoint_check.hpp"

#include "divergence2d_adjoint.hpp"
#include "divergence2d_tangent.hpp"
#include "kernels.hpp"

#include <type_traits>

static_assert(std::is_same_v<decltype(&divergence2d_adjoint),
                             void (*)(const double*, double*, const double*, double*,
                                      const double*, int, int, double)>);

TEST_CASE("divergence2d adjoint") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {3, 3}, {4, 7}, {9, 5}, {16, 13}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const double h = 0.25;
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { divergence2d(in[0], in[1], out[0], nx, ny, h); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      divergence2d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, h);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      divergence2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, h);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      divergence2d_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, h);
    };
    dpgen_test::check_adjoint(p);
  }
}
