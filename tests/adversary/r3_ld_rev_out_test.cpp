// r3_ld_rev_out (tests/adversary/): sizes (nx,ny,ld) in {{1,1,1},{2,2,2},{3,2,4},{2,3,5},{4,3,4}}.
#include "adv.hpp"
#include "r3_ld_rev_out_adjoint.hpp"
#include "r3_ld_rev_out_tangent.hpp"
#include <tuple>
void r3_ld_rev_out(const double*, double*, int nx, int ny, int ld);
TEST_CASE("adversary: r3_ld_rev_out") {
  for (auto [nx,ny,ld] : std::initializer_list<std::tuple<int,int,int>>{{1,1,1},{2,2,2},{3,2,4},{2,3,5},{4,3,4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(ld);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(ny*ld)};
    p.out_sizes = {ADV_SZ(ny*ld)};
    p.forward = [&](auto in, auto out) { r3_ld_rev_out(in[0], out[0], nx, ny, ld); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_ld_rev_out_adjoint(in[0], adj[0], seed[0], nx, ny, ld); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_ld_rev_out_tangent(in[0], dir[0], out[0], od[0], nx, ny, ld); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) { r3_ld_rev_out_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, ld); };
    dpgen_test::check_adjoint(p);
  }
}
