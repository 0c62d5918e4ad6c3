// mac_divergence2d (tests/kernels/): staggered layouts (nx+1)*ny and nx*(ny+1).
#include "support/adjoint_check.hpp"

#include "mac_divergence2d_adjoint.hpp"
#include "mac_divergence2d_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("mac_divergence2d adjoint") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {5, 4}, {10, 7}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t((nx + 1) * ny), size_t(nx * (ny + 1))};
    p.out_sizes = {size_t(nx * ny)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { mac_divergence2d(in[0], in[1], out[0], nx, ny, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mac_divergence2d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.2);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mac_divergence2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      mac_divergence2d_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}
