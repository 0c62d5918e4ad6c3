// gradient2d (tests/kernels/): two outputs, branches at every boundary.
#include "support/adjoint_check.hpp"

#include "gradient2d_adjoint.hpp"
#include "gradient2d_tangent.hpp"
#include "test_kernels.hpp"

#include <type_traits>

// Two DPGEN_OUT arrays -> two read-only seeds, in parameter order.
static_assert(std::is_same_v<decltype(&gradient2d_adjoint),
                             void (*)(const double*, double*, const double*, const double*, int,
                                      int, double)>);

TEST_CASE("gradient2d adjoint") {
  for (auto [nx, ny] : {std::pair{2, 2}, {3, 2}, {4, 5}, {11, 8}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n, n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { gradient2d(in[0], out[0], out[1], nx, ny, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      gradient2d_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      gradient2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], nx, ny, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      gradient2d_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}
