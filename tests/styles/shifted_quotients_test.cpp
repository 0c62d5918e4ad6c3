// shifted_quotients (tests/styles/): quotients and square roots computed per cell and needed by
// the adjoint at neighbouring cells (shared along strips of 256 cells: sizes below, at and above
// one strip, several strips, and enough cells for the threaded loop).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "shifted_quotients_adjoint.hpp"
#include "shifted_quotients_tangent.hpp"

#include <cmath>
#include <tuple>
#include <vector>

DPGEN_KERNEL void centred_speed(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                DPGEN_OUT double* qn, int n, double dx);
DPGEN_KERNEL void sqrt_conductivity2d(DPGEN_IN const float* phi, DPGEN_OUT float* out, int nx,
                                      int ny, float dt);
DPGEN_KERNEL void ratio_in_branch(DPGEN_IN const double* q, DPGEN_OUT double* out, int n);

TEST_CASE("styles: shifted_quotients, centred_speed") {
  for (int n : {1, 2, 3, 5, 13, 256, 257, 258, 600, 8300}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { centred_speed(in[0], in[1], out[0], n, 0.4); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      centred_speed_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.4);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      centred_speed_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.4);
    };
    dpgen_test::check_adjoint(p);

    // q's adjoint alone (u's null: the loop of q alone, with its own strips) is q's adjoint of
    // the fused loop of both.
    std::vector<double> q(n), u(n), seed(n), both(n, 0.0), alone(n, 0.0), u_adj(n, 0.0);
    for (int i = 0; i < n; ++i) {
      q[i] = std::sin(0.7 * i);
      u[i] = std::cos(1.3 * i) - 0.2;
      seed[i] = std::sin(0.3 * i + 1.0);
    }
    centred_speed_adjoint(q.data(), both.data(), u.data(), u_adj.data(), seed.data(), n, 0.4);
    centred_speed_adjoint(q.data(), alone.data(), u.data(), nullptr, seed.data(), n, 0.4);
    for (int i = 0; i < n; ++i)
      REQUIRE(alone[i] == doctest::Approx(both[i]).epsilon(1e-14));
  }
}

TEST_CASE("styles: shifted_quotients, sqrt_conductivity2d") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 3}, {6, 5}, {300, 4}, {530, 3}, {520, 17}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    // Away from |phi|'s kink at 0, where float finite differences across it would fail.
    p.in_ranges = {{0.1, 1.0}};
    p.forward = [&](auto in, auto out) { sqrt_conductivity2d(in[0], out[0], nx, ny, 0.05f); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      sqrt_conductivity2d_adjoint(in[0], adj[0], seed[0], nx, ny, 0.05f);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      sqrt_conductivity2d_tangent(in[0], dir[0], out[0], outd[0], nx, ny, 0.05f);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: shifted_quotients, ratio_in_branch") {
  for (int n : {1, 3, 13, 257, 600}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { ratio_in_branch(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      ratio_in_branch_adjoint(in[0], adj[0], seed[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
