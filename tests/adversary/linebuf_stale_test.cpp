// linebuf_stale (tests/adversary/): a function-scope line buffer double buf[16] (nx <= 16).
#include "adv.hpp"
#include "linebuf_stale_adjoint.hpp"
#include "linebuf_stale_tangent.hpp"
void linebuf_stale(const double* a, double* out, int nx, int ny);
TEST_CASE("adversary: linebuf_stale") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 1}, {3, 2}, {4, 3}, {16, 2}}) {
    CAPTURE(nx); CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(nx * ny)};
    p.out_sizes = {ADV_SZ(nx * ny)};
    p.forward = [&](auto in, auto out) { linebuf_stale(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) { linebuf_stale_adjoint(in[0], adj[0], seed[0], nx, ny); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { linebuf_stale_tangent(in[0], dir[0], out[0], od[0], nx, ny); };
    dpgen_test::check_adjoint(p);
  }
}
