// laplacian3d (tests/kernels/): 3D 7-point, linear.
#include "support/adjoint_check.hpp"

#include "laplacian3d_adjoint.hpp"
#include "laplacian3d_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("laplacian3d adjoint") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {3, 3, 3}, {4, 5, 3}, {7, 6, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    size_t n = size_t(nx * ny * nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { laplacian3d(in[0], out[0], nx, ny, nz, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplacian3d_adjoint(in[0], adj[0], seed[0], nx, ny, nz, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      laplacian3d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, nz, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      laplacian3d_tangent(in[0], dir[0], out[0], outd[0], nx, ny, nz, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}
