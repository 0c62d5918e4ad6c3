// wave2d_rowptr_scattered (tests/styles/): rows in separate heap blocks with
// guard cells, allocated last row first; adjoint and tangent take row
// pointers of the same shape.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "styles_support.hpp"
#include "wave2d_rowptr_scattered_adjoint.hpp"
#include "wave2d_rowptr_scattered_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void wave2d_rowptr_scattered(DPGEN_IN double** u, DPGEN_IN double** c,
                                          DPGEN_OUT double** un, int nx, int ny, double dt);

TEST_CASE("styles: wave2d_rowptr_scattered") {
  using R = styles::ScatteredRows<double>;
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 3}, {4, 5}, {7, 3}, {9, 8}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny), w = size_t(nx), h = size_t(ny);
    const double dt = 0.1;
    bool guards = true;
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      R u(h, w), c(h, w), un(h, w);
      u.load(in[0]), c.load(in[1]), un.load(out[0]);
      wave2d_rowptr_scattered(u.data(), c.data(), un.data(), nx, ny, dt);
      un.save(out[0]);
      guards = guards && un.guards_intact();
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      R u(h, w), c(h, w), ua(h, w), ca(h, w), s(h, w);
      u.load(in[0]), c.load(in[1]), ua.load(adj[0]), ca.load(adj[1]), s.load(seed[0]);
      wave2d_rowptr_scattered_adjoint(u.data(), ua.data(), c.data(), ca.data(), s.data(), nx, ny,
                                      dt);
      ua.save(adj[0]), ca.save(adj[1]);
      guards = guards && ua.guards_intact() && ca.guards_intact();
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      R u(h, w), c(h, w), ud(h, w), cd(h, w), un(h, w), und(h, w);
      u.load(in[0]), c.load(in[1]), ud.load(dir[0]), cd.load(dir[1]), un.load(out[0]),
          und.load(outd[0]);
      wave2d_rowptr_scattered_tangent(u.data(), ud.data(), c.data(), cd.data(), un.data(),
                                      und.data(), nx, ny, dt);
      un.save(out[0]), und.save(outd[0]);
      guards = guards && un.guards_intact() && und.guards_intact();
    };
    dpgen_test::check_adjoint(p);
    CHECK(guards);
  }
}
