// r3_3d_long_szt (tests/adversary/): sizes (nx,ny,nz) in {{1,1,1},{2,1,3},{3,2,2},{1,3,4},{4,3,5}}.
#include "adv.hpp"
#include "r3_3d_long_szt_adjoint.hpp"
#include "r3_3d_long_szt_tangent.hpp"
#include <tuple>
void r3_3d_long_szt(const double*, double*, size_t nx, size_t ny, size_t nz);
TEST_CASE("adversary: r3_3d_long_szt") {
  for (auto [nx,ny,nz] : std::initializer_list<std::tuple<size_t,size_t,size_t>>{{1,1,1},{2,1,3},{3,2,2},{1,3,4},{4,3,5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(nx*ny*nz)};
    p.out_sizes = {ADV_SZ(nx*ny*nz)};
    p.forward = [&](auto in, auto out) { r3_3d_long_szt(in[0], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_3d_long_szt_adjoint(in[0], adj[0], seed[0], nx, ny, nz); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_3d_long_szt_tangent(in[0], dir[0], out[0], od[0], nx, ny, nz); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) { r3_3d_long_szt_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, nz); };
    dpgen_test::check_adjoint(p);
  }
}
