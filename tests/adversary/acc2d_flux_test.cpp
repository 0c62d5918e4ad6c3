// acc2d_flux (tests/adversary/): 2D flux accumulation (`-=`/`+=` into two
// cells per face) after a zeroing nest, x faces then y faces.
#include "adv.hpp"
#include "acc2d_flux_adjoint.hpp"
#include "acc2d_flux_tangent.hpp"
void acc2d_flux(const double* u, double* r, int nx, int ny);
TEST_CASE("adversary: acc2d_flux") {
  for (auto [nx, ny] : {std::pair{0, 0}, {1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 4}, {5, 3}}) {
    CAPTURE(nx); CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(nx * ny)};
    p.out_sizes = {ADV_SZ(nx * ny)};
    p.forward = [&](auto in, auto out) { acc2d_flux(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) { acc2d_flux_adjoint(in[0], adj[0], seed[0], nx, ny); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { acc2d_flux_tangent(in[0], dir[0], out[0], od[0], nx, ny); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      acc2d_flux_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
