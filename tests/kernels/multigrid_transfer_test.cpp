// multigrid_transfer (kernels/): the prolongation kernels' generated adjoints are the multigrid's
// restriction (R = P^T / 4), so they are checked here like every other adjoint, for each
// boundary condition's ghost weights; and P reproduces the constants where it must.
#include "support/adjoint_check.hpp"

#include "kernels.hpp"
#include "multigrid_transfer_adjoint.hpp"

#include <vector>

namespace {
// (self, wrap) ghost weights: periodic, Neumann, Dirichlet; and arbitrary values.
const std::vector<std::pair<double, double>> kGhosts = {{0, 1}, {1, 0}, {-1, 0}, {0.3, -0.7}};
} // namespace

TEST_CASE("mg_prolong_x adjoint") {
  for (auto [nxc, ny] : {std::pair{1, 1}, {1, 3}, {2, 2}, {3, 2}, {5, 4}, {8, 3}})
    for (auto [lo_self, lo_wrap] : kGhosts)
      for (auto [hi_self, hi_wrap] : kGhosts) {
        CAPTURE(nxc);
        CAPTURE(ny);
        CAPTURE(lo_self);
        CAPTURE(hi_wrap);
        dpgen_test::Problem<double> p;
        p.in_sizes = {size_t(nxc * ny)};
        p.out_sizes = {size_t(2 * nxc * ny)};
        p.linear = true;
        p.forward = [&](auto in, auto out) {
          mg_prolong_x(in[0], out[0], nxc, ny, lo_self, lo_wrap, hi_self, hi_wrap);
        };
        p.adjoint = [&](auto in, auto adj, auto seed) {
          mg_prolong_x_adjoint(in[0], adj[0], seed[0], nxc, ny, lo_self, lo_wrap, hi_self, hi_wrap);
        };
        p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
          mg_prolong_x_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nxc, ny, lo_self, lo_wrap, hi_self, hi_wrap);
        };
        dpgen_test::check_adjoint(p);
      }
}

TEST_CASE("mg_prolong_y adjoint") {
  for (auto [nxc, nyc] : {std::pair{1, 1}, {1, 3}, {2, 2}, {3, 2}, {4, 5}, {3, 8}})
    for (auto [lo_self, lo_wrap] : kGhosts)
      for (auto [hi_self, hi_wrap] : kGhosts) {
        CAPTURE(nxc);
        CAPTURE(nyc);
        dpgen_test::Problem<double> p;
        p.in_sizes = {size_t(2 * nxc * nyc)};
        p.out_sizes = {size_t(4 * nxc * nyc)};
        p.linear = true;
        p.forward = [&](auto in, auto out) {
          mg_prolong_y(in[0], out[0], nxc, nyc, lo_self, lo_wrap, hi_self, hi_wrap);
        };
        p.adjoint = [&](auto in, auto adj, auto seed) {
          mg_prolong_y_adjoint(in[0], adj[0], seed[0], nxc, nyc, lo_self, lo_wrap, hi_self,
                               hi_wrap);
        };
        p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
          mg_prolong_y_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nxc, nyc, lo_self, lo_wrap, hi_self, hi_wrap);
        };
        dpgen_test::check_adjoint(p);
      }
}

TEST_CASE("mg_average_2x2 adjoint") {
  for (auto [nxc, nyc] : {std::pair{1, 1}, {2, 3}, {5, 4}}) {
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(4 * nxc * nyc)};
    p.out_sizes = {size_t(nxc * nyc)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { mg_average_2x2(in[0], out[0], nxc, nyc); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mg_average_2x2_adjoint(in[0], adj[0], seed[0], nxc, nyc);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mg_average_2x2_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nxc, nyc);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("bilinear prolongation: constants stay constant (periodic, Neumann), Dirichlet "
          "ghosts halve the edge cells, interior weights 9/16 3/16 3/16 1/16") {
  const int nxc = 4, nyc = 3;
  std::vector<double> c(nxc * nyc, 2.0), t(2 * nxc * nyc), f(4 * nxc * nyc);
  for (auto [self, wrap] : {std::pair{0.0, 1.0}, {1.0, 0.0}}) {
    mg_prolong_x(c.data(), t.data(), nxc, nyc, self, wrap, self, wrap);
    mg_prolong_y(t.data(), f.data(), nxc, nyc, self, wrap, self, wrap);
    for (double v : f)
      CHECK(v == doctest::Approx(2.0).epsilon(1e-15));
  }
  mg_prolong_x(c.data(), t.data(), nxc, nyc, -1, 0, -1, 0);
  mg_prolong_y(t.data(), f.data(), nxc, nyc, -1, 0, -1, 0);
  const int nx = 2 * nxc;
  CHECK(f[0] == doctest::Approx(0.5)); // 2 * (1/2 in x) * (1/2 in y)
  CHECK(f[nx + 3] == doctest::Approx(2.0));
  // A single coarse spike: the 4x4 block around it carries 9/16, 3/16, 1/16.
  std::vector<double> spike(nxc * nyc, 0.0);
  spike[1 * nxc + 1] = 16.0;
  mg_prolong_x(spike.data(), t.data(), nxc, nyc, 0, 1, 0, 1);
  mg_prolong_y(t.data(), f.data(), nxc, nyc, 0, 1, 0, 1);
  CHECK(f[2 * nx + 2] == doctest::Approx(9.0));
  CHECK(f[2 * nx + 1] == doctest::Approx(3.0));
  CHECK(f[1 * nx + 2] == doctest::Approx(3.0));
  CHECK(f[1 * nx + 1] == doctest::Approx(1.0));
  CHECK(f[0 * nx + 2] == doctest::Approx(0.0));
}
