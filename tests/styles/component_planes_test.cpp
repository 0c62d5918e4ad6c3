// component_planes (tests/styles/): adjoint and tangent of component planes
// in one flat array (planes apart by products of sizes, or by a stride the
// generated code checks on entry).
#include "support/adjoint_check.hpp"

#include "component_planes_adjoint.hpp"
#include "component_planes_kernels.hpp"
#include "component_planes_tangent.hpp"

#include <stdexcept>

TEST_CASE("styles: planes_faces") {
  for (auto [nx, ny] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {3 * Y * (X + 2)};
    p.out_sizes = {3 * Y * (X + 1), 3 * Y * X};
    p.forward = [&](auto in, auto out) { planes_faces(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      planes_faces_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      planes_faces_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: planes_nodes3d") {
  for (auto n : {0, 1, 3}) {
    CAPTURE(n);
    const int nx = n, ny = n + 1, nz = 2;
    const size_t N = size_t(nx + 1) * size_t(ny + 1) * size_t(nz + 1);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {3 * N};
    p.forward = [&](auto in, auto out) { planes_nodes3d(in[0], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      planes_nodes3d_adjoint(in[0], adj[0], seed[0], nx, ny, nz);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      planes_nodes3d_tangent(in[0], d[0], out[0], dout[0], nx, ny, nz);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: planes_strided") {
  for (int n : {1, 2, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {3 * N};
    p.forward = [&](auto in, auto out) { planes_strided(in[0], out[0], n, n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      planes_strided_adjoint(in[0], adj[0], seed[0], n, n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      planes_strided_tangent(in[0], d[0], out[0], dout[0], n, n);
    };
    dpgen_test::check_adjoint(p);
  }
  // Planes that overlap (stride < n): the entry check stops both.
  double u[4] = {1, 2, 3, 4}, u_adj[4] = {0, 0, 0, 0}, seed[12] = {}, out[12], out_dot[12];
  CHECK_THROWS_AS(planes_strided_adjoint(u, u_adj, seed, 4, 3), std::invalid_argument);
  CHECK_THROWS_AS(planes_strided_tangent(u, u_adj, out, out_dot, 4, 3), std::invalid_argument);
}
