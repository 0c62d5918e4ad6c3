// r3_3d_uns_7pt (tests/adversary/): sizes (nx,ny,nz) in {{1,1,1},{3,3,3},{4,3,5},{3,4,3},{0,3,3}}.
#include "adv.hpp"
#include "r3_3d_uns_7pt_adjoint.hpp"
#include "r3_3d_uns_7pt_tangent.hpp"
#include <tuple>
void r3_3d_uns_7pt(const double*, double*, unsigned nx, unsigned ny, unsigned nz);
TEST_CASE("adversary: r3_3d_uns_7pt") {
  for (auto [nx,ny,nz] : std::initializer_list<std::tuple<unsigned,unsigned,unsigned>>{{1,1,1},{3,3,3},{4,3,5},{3,4,3},{0,3,3}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(nx*ny*nz)};
    p.out_sizes = {ADV_SZ(nx*ny*nz)};
    p.forward = [&](auto in, auto out) { r3_3d_uns_7pt(in[0], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_3d_uns_7pt_adjoint(in[0], adj[0], seed[0], nx, ny, nz); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_3d_uns_7pt_tangent(in[0], dir[0], out[0], od[0], nx, ny, nz); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) { r3_3d_uns_7pt_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, nz); };
    dpgen_test::check_adjoint(p);
  }
}
