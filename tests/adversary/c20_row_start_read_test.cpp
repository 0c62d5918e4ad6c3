// c20_row_start_read (tests/adversary/): see c20_row_start_read.cpp; arrays
// of exactly nx * ny cells, nx in {0, 1, 3}, ny in {0, 1, 3}.
#include "adv.hpp"
#include "c20_row_start_read_adjoint.hpp"
#include "c20_row_start_read_tangent.hpp"
void c20_row_start_read(const double*, double*, int nx, int ny);
TEST_CASE("adversary: c20_row_start_read") {
  for (int nx : {0, 1, 3})
    for (int ny : {0, 1, 3}) {
      CAPTURE(nx);
      CAPTURE(ny);
      dpgen_test::Problem<double> p;
      p.in_sizes = {ADV_SZ(nx * ny)};
      p.out_sizes = {ADV_SZ(nx * ny)};
      p.forward = [&](auto in, auto out) { c20_row_start_read(in[0], out[0], nx, ny); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        c20_row_start_read_adjoint(in[0], adj[0], seed[0], nx, ny);
      };
      p.tangent = [&](auto in, auto dir, auto out, auto od) {
        c20_row_start_read_tangent(in[0], dir[0], out[0], od[0], nx, ny);
      };
      p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
        c20_row_start_read_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0],
                                           nx, ny);
      };
      dpgen_test::check_adjoint(p);
    }
}
