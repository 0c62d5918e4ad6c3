// flat3d_interior (tests/adversary/): interior-only 3D nest, int flat index
// built from strides held in int locals.
#include "adv.hpp"
#include "flat3d_interior_adjoint.hpp"
#include "flat3d_interior_tangent.hpp"
void flat3d_interior(const double* u, const double* k, double* out, int nx, int ny, int nz);
TEST_CASE("adversary: flat3d_interior") {
  for (auto [nx, ny, nz] : {std::tuple{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 3, 5}, {3, 5, 4}, {5, 4, 3}}) {
    CAPTURE(nx); CAPTURE(ny); CAPTURE(nz);
    size_t s = ADV_SZ(nx * ny * nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {s, s};
    p.out_sizes = {s};
    p.forward = [&](auto in, auto out) { flat3d_interior(in[0], in[1], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) { flat3d_interior_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, nz); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { flat3d_interior_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], nx, ny, nz); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flat3d_interior_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, nz);
    };
    dpgen_test::check_adjoint(p);
  }
}
