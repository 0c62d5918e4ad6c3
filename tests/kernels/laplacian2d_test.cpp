// laplacian2d (kernels/): signature rule, adjoint checks (linear).
#include "support/adjoint_check.hpp"

#include "kernels.hpp"
#include "laplacian2d_adjoint.hpp"
#include "laplacian2d_tangent.hpp"

#include <type_traits>

static_assert(std::is_same_v<decltype(&laplacian2d_adjoint),
                             void (*)(const double*, double*, const double*, int, int, double)>);

TEST_CASE("laplacian2d adjoint") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 2}, {3, 3}, {4, 4}, {5, 8}, {17, 11}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const double h = 0.5;
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { laplacian2d(in[0], out[0], nx, ny, h); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplacian2d_adjoint(in[0], adj[0], seed[0], nx, ny, h);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      laplacian2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, h);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      laplacian2d_tangent(in[0], dir[0], out[0], outd[0], nx, ny, h);
    };
    dpgen_test::check_adjoint(p);
  }
}
