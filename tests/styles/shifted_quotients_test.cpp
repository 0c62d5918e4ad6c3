// shifted_quotients (tests/styles/): quotients and square roots computed per cell and needed by
// the adjoint at neighbouring cells (shared along strips of 256 cells: sizes below, at and above
// one strip, several strips, and enough cells for the threaded loop).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "shifted_quotients_adjoint.hpp"
#include "shifted_quotients_tangent.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

DPGEN_KERNEL void centred_speed(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                DPGEN_OUT double* qn, int n, double dx);
DPGEN_KERNEL void sqrt_conductivity2d(DPGEN_IN const float* phi, DPGEN_OUT float* out, int nx,
                                      int ny, float dt);
DPGEN_KERNEL void ninepoint_weights(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny);
DPGEN_KERNEL void ratio_in_branch(DPGEN_IN const double* q, DPGEN_OUT double* out, int n);
DPGEN_KERNEL void flux_form_upwind(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                   DPGEN_OUT double* qn, int n, double dt, double dx);
DPGEN_KERNEL void mirrored_weights(DPGEN_IN const double* q, const double* w, DPGEN_OUT double* out,
                                   int n);
DPGEN_KERNEL void gaussian_neighbours(DPGEN_IN const double* q, DPGEN_OUT double* out, int n,
                                      double inv_two_s2);

namespace {

// The checker surrounds every array with guard cells, which a strip's buffer reading a few
// cells too far would not notice: the adjoint once more on arrays of exactly the kernel's size
// (a read past them is a heap overflow to the sanitizer build), giving the same result.
template <typename T, typename Adjoint>
void same_on_exact_arrays(size_t n, const dpgen_test::Problem<T>& p, Adjoint adjoint) {
  std::vector<T> in(n), seed(n), exact(n, T(0));
  for (size_t i = 0; i < n; ++i) {
    in[i] = T(0.2 + 0.7 * std::fabs(std::sin(0.37 * double(i) + 0.1)));
    seed[i] = T(std::cos(0.53 * double(i)));
  }
  adjoint(in.data(), exact.data(), seed.data());
  std::vector<T> padded_in(n + 64, T(0)), padded_seed(n + 64, T(0)), padded(n + 64, T(0));
  std::copy(in.begin(), in.end(), padded_in.begin() + 32);
  std::copy(seed.begin(), seed.end(), padded_seed.begin() + 32);
  p.adjoint({padded_in.data() + 32}, {padded.data() + 32}, {padded_seed.data() + 32});
  for (size_t i = 0; i < n; ++i)
    REQUIRE(exact[i] == padded[i + 32]);
}

} // namespace

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
    // the fused loop of both: the same terms in the same order (bit for bit with plain -O3;
    // where the compiler contracts multiply-adds, -march=native, it may fuse them otherwise in
    // the two loops).
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
    same_on_exact_arrays<float>(n, p, [&](const float* in, float* adj, const float* seed) {
      sqrt_conductivity2d_adjoint(in, adj, seed, nx, ny, 0.05f);
    });
  }
}

TEST_CASE("styles: shifted_quotients, ninepoint_weights") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 3}, {7, 4}, {260, 5}, {600, 3}, {300, 30}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.in_ranges = {{0.1, 1.0}}; // (away from |a|'s kink)
    p.forward = [&](auto in, auto out) { ninepoint_weights(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      ninepoint_weights_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      ninepoint_weights_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
    same_on_exact_arrays<double>(n, p, [&](const double* in, double* adj, const double* seed) {
      ninepoint_weights_adjoint(in, adj, seed, nx, ny);
    });
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

TEST_CASE("styles: shifted_quotients, flux_form_upwind") {
  // The face speeds' signs decide the upwind cell: all faces one way, then the other (finite
  // differences across a switch would fail). u's adjoint alone on exact arrays after that.
  for (auto [lo, hi] : {std::pair{0.2, 1.0}, {-1.0, -0.2}})
    for (int n : {1, 2, 3, 5, 13, 256, 257, 258, 600, 8300}) {
      CAPTURE(n);
      CAPTURE(lo);
      dpgen_test::Problem<double> p;
      p.in_sizes = {size_t(n), size_t(n)};
      p.out_sizes = {size_t(n)};
      p.in_ranges = {{-1.0, 1.0}, {lo, hi}};
      p.forward = [&](auto in, auto out) { flux_form_upwind(in[0], in[1], out[0], n, 0.1, 0.4); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        flux_form_upwind_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.1, 0.4);
      };
      p.tangent = [&](auto in, auto dir, auto out, auto outd) {
        flux_form_upwind_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.1, 0.4);
      };
      dpgen_test::check_adjoint(p);
    }
  for (int n : {3, 257, 600}) {
    CAPTURE(n);
    const std::vector<double> q(size_t(n), 0.5);
    dpgen_test::Problem<double> p;
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flux_form_upwind_adjoint(q.data(), nullptr, in[0], adj[0], seed[0], n, 0.1, 0.4);
    };
    same_on_exact_arrays<double>(
        size_t(n), p, [&](const double* u, double* u_adj, const double* seed) {
          flux_form_upwind_adjoint(q.data(), nullptr, u, u_adj, seed, n, 0.1, 0.4);
        });
  }
}

TEST_CASE("styles: shifted_quotients, mirrored_weights") {
  for (int n : {1, 2, 3, 5, 13, 256, 257, 258, 600, 8300}) {
    CAPTURE(n);
    std::vector<double> w(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
      w[size_t(i)] = std::sin(0.9 * i + 0.3);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { mirrored_weights(in[0], w.data(), out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mirrored_weights_adjoint(in[0], adj[0], w.data(), seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      mirrored_weights_tangent(in[0], dir[0], w.data(), out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
    // (the weights are read at n - 1 - i and n - 2 - i: exactly w's size)
    same_on_exact_arrays<double>(size_t(n), p,
                                 [&](const double* in, double* adj, const double* seed) {
                                   mirrored_weights_adjoint(in, adj, w.data(), seed, n);
                                 });
  }
}

TEST_CASE("styles: shifted_quotients, gaussian_neighbours") {
  for (int n : {1, 2, 3, 5, 13, 256, 257, 258, 600, 8300}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { gaussian_neighbours(in[0], out[0], n, 0.7); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      gaussian_neighbours_adjoint(in[0], adj[0], seed[0], n, 0.7);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      gaussian_neighbours_tangent(in[0], dir[0], out[0], outd[0], n, 0.7);
    };
    dpgen_test::check_adjoint(p);
    same_on_exact_arrays<double>(size_t(n), p,
                                 [&](const double* in, double* adj, const double* seed) {
                                   gaussian_neighbours_adjoint(in, adj, seed, n, 0.7);
                                 });
  }
}
