// r3_2d_uns_rev (tests/adversary/): sizes (nx,ny) in {{0,0},{1,1},{2,1},{1,3},{3,2},{4,5}}.
#include "adv.hpp"
#include "r3_2d_uns_rev_adjoint.hpp"
#include "r3_2d_uns_rev_tangent.hpp"
#include <tuple>
void r3_2d_uns_rev(const double*, double*, unsigned nx, unsigned ny);
TEST_CASE("adversary: r3_2d_uns_rev") {
  for (auto [nx,ny] : std::initializer_list<std::tuple<unsigned,unsigned>>{{0,0},{1,1},{2,1},{1,3},{3,2},{4,5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(nx*ny)};
    p.out_sizes = {ADV_SZ(nx*ny)};
    p.forward = [&](auto in, auto out) { r3_2d_uns_rev(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_2d_uns_rev_adjoint(in[0], adj[0], seed[0], nx, ny); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_2d_uns_rev_tangent(in[0], dir[0], out[0], od[0], nx, ny); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) { r3_2d_uns_rev_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny); };
    dpgen_test::check_adjoint(p);
  }
}
