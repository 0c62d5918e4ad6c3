// vector_sums (tests/styles/): std::vector kernels with work arrays (a local sum read after
// its loop; an output vector a later loop reads), adjoint and tangent against differences
// and the dot-product test, the normalisation's adjoint by hand, and a seed shorter than
// the output refused; vector_scaled_prefix: an int bound past a vector's size refused by the
// adjoint and the tangent; vector_guarded_pairs: outputs shorter than the input, written under
// a condition, and vector_fluxes with outputs as long as what it writes. The checker's flat
// arrays are copied into vectors and back.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "styles_support.hpp"
#include "vector_sums_adjoint.hpp"
#include "vector_sums_kernels.hpp"
#include "vector_sums_tangent.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

TEST_CASE("styles: vector_normalize") {
  for (int n : {1, 2, 7, 30}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      std::vector<double> a = styles::to_vec(in[0], N), u = styles::to_vec(out[0], N);
      vector_normalize(a, u);
      styles::from_vec(u, out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> a = styles::to_vec(in[0], N), aa = styles::to_vec(adj[0], N),
                          s = styles::to_vec(seed[0], N);
      vector_normalize_adjoint(a, aa, s);
      styles::from_vec(aa, adj[0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      std::vector<double> a = styles::to_vec(in[0], N), da = styles::to_vec(dir[0], N),
                          u = styles::to_vec(out[0], N), du = styles::to_vec(outd[0], N);
      vector_normalize_tangent(a, da, u, du);
      styles::from_vec(u, out[0]);
      styles::from_vec(du, outd[0]);
    };
    dpgen_test::check_adjoint(p);
  }
  // By hand: u = a / |a|, so J^T s = (s - u (u . s)) / |a|. a = (3, 4), s = (1, 0):
  // u = (0.6, 0.8), u . s = 0.6, J^T s = ((1 - 0.36) / 5, -0.48 / 5).
  const std::vector<double> a = {3.0, 4.0}, s = {1.0, 0.0};
  std::vector<double> adj = {0.0, 0.0};
  vector_normalize_adjoint(a, adj, s);
  CHECK(adj[0] == doctest::Approx(0.64 / 5.0));
  CHECK(adj[1] == doctest::Approx(-0.48 / 5.0));
}

TEST_CASE("styles: vector_fluxes") {
  for (int n : {0, 1, 2, 3, 11}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) {
      std::vector<double> u = styles::to_vec(in[0], N), f = styles::to_vec(out[0], N),
                          d = styles::to_vec(out[1], N);
      vector_fluxes(u, f, d, 0.3);
      styles::from_vec(f, out[0]);
      styles::from_vec(d, out[1]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> u = styles::to_vec(in[0], N), ua = styles::to_vec(adj[0], N),
                          fs = styles::to_vec(seed[0], N), ds = styles::to_vec(seed[1], N);
      vector_fluxes_adjoint(u, ua, fs, ds, 0.3);
      styles::from_vec(ua, adj[0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      std::vector<double> u = styles::to_vec(in[0], N), du = styles::to_vec(dir[0], N),
                          f = styles::to_vec(out[0], N), df = styles::to_vec(outd[0], N),
                          d = styles::to_vec(out[1], N), dd = styles::to_vec(outd[1], N);
      vector_fluxes_tangent(u, du, f, df, d, dd, 0.3);
      styles::from_vec(f, out[0]);
      styles::from_vec(df, outd[0]);
      styles::from_vec(d, out[1]);
      styles::from_vec(dd, outd[1]);
    };
    dpgen_test::check_adjoint(p);
  } // A seed shorter than the output the kernel writes: refused before anything is read.
  const std::vector<double> u(6, 1.0), short_seed(4, 1.0), seed(6, 1.0);
  std::vector<double> adj(6, 0.0);
  CHECK_THROWS_WITH_AS(vector_fluxes_adjoint(u, adj, short_seed, seed, 0.3),
                       "vector_fluxes_adjoint: 'flux_adj' has 4 elements, but the kernel touches "
                       "elements 0 to 4",
                       std::invalid_argument);
  CHECK_THROWS_AS(vector_fluxes_adjoint(u, adj, seed, short_seed, 0.3), std::invalid_argument);
  CHECK(adj == std::vector<double>(6, 0.0));
}

TEST_CASE("styles: vector_scaled_prefix, an int bound checked against the vectors' sizes") {
  for (int n : {0, 1, 4}) {
    CAPTURE(n);
    const size_t N = 6;
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      std::vector<double> a = styles::to_vec(in[0], N), w = styles::to_vec(out[0], N);
      vector_scaled_prefix(a, w, n);
      styles::from_vec(w, out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> a = styles::to_vec(in[0], N), aa = styles::to_vec(adj[0], N),
                          s = styles::to_vec(seed[0], N);
      vector_scaled_prefix_adjoint(a, aa, s, n);
      styles::from_vec(aa, adj[0]);
    };
    dpgen_test::check_adjoint(p);
  }
  // n past a's size: the forward would read beyond it; the adjoint and tangent say so.
  const std::vector<double> a(5, 1.0), seed(8, 1.0);
  std::vector<double> adj(5, 0.0), w(8), dw(8);
  CHECK_THROWS_WITH_AS(vector_scaled_prefix_adjoint(a, adj, seed, 8),
                       "vector_scaled_prefix_adjoint: 'a' has 5 elements, but the kernel touches "
                       "elements 0 to 7",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(vector_scaled_prefix_tangent(a, a, w, dw, 8),
                       "vector_scaled_prefix_tangent: 'a' has 5 elements, but the kernel touches "
                       "elements 0 to 7",
                       std::invalid_argument);
  // and a seed shorter than what the kernel writes
  const std::vector<double> a8(8, 1.0), seed4(4, 1.0);
  std::vector<double> adj8(8, 0.0);
  CHECK_THROWS_WITH_AS(vector_scaled_prefix_adjoint(a8, adj8, seed4, 8),
                       "vector_scaled_prefix_adjoint: 'w_adj' has 4 elements, but the kernel "
                       "touches elements 0 to 7",
                       std::invalid_argument);
  std::vector<double> w4(4), dw4(4);
  CHECK_THROWS_WITH_AS(vector_scaled_prefix_tangent(a8, a8, w4, dw4, 8),
                       "vector_scaled_prefix_tangent: 'w' has 4 elements, but the kernel touches "
                       "elements 0 to 7",
                       std::invalid_argument);
  CHECK(adj == std::vector<double>(5, 0.0));
  CHECK(adj8 == std::vector<double>(8, 0.0));
}

TEST_CASE("styles: vector_guarded_pairs, outputs one shorter than the input") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    const size_t N = size_t(n), M = N - 1;
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {M, M};
    p.forward = [&](auto in, auto out) {
      std::vector<double> u = styles::to_vec(in[0], N), f = styles::to_vec(out[0], M),
                          g = styles::to_vec(out[1], M);
      vector_guarded_pairs(u, f, g);
      styles::from_vec(f, out[0]);
      styles::from_vec(g, out[1]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> u = styles::to_vec(in[0], N), ua = styles::to_vec(adj[0], N),
                          fs = styles::to_vec(seed[0], M), gs = styles::to_vec(seed[1], M);
      vector_guarded_pairs_adjoint(u, ua, fs, gs);
      styles::from_vec(ua, adj[0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      std::vector<double> u = styles::to_vec(in[0], N), du = styles::to_vec(dir[0], N),
                          f = styles::to_vec(out[0], M), df = styles::to_vec(outd[0], M),
                          g = styles::to_vec(out[1], M), dg = styles::to_vec(outd[1], M);
      vector_guarded_pairs_tangent(u, du, f, df, g, dg);
      styles::from_vec(f, out[0]);
      styles::from_vec(df, outd[0]);
      styles::from_vec(g, out[1]);
      styles::from_vec(dg, outd[1]);
    };
    dpgen_test::check_adjoint(p);
  }
  // vector_fluxes with the outputs as long as what it writes: u of 2, flux of 1, du empty
  // (its loop runs no iteration), the same gradient as with full-length seeds.
  const std::vector<double> u = {0.7, -0.4}, flux_seed = {1.0}, du_seed = {};
  std::vector<double> adj(2, 0.0), full(2, 0.0);
  vector_fluxes_adjoint(u, adj, flux_seed, du_seed, 0.3);
  vector_fluxes_adjoint(u, full, {1.0, 0.0}, {0.0, 0.0}, 0.3);
  CHECK(adj == full);
  const double m = 0.5 * (u[0] + u[1]); // flux[0] = m^2 / 2: d/du0 = d/du1 = m / 2
  CHECK(adj[0] == doctest::Approx(0.5 * m));
  CHECK(adj[1] == doctest::Approx(0.5 * m));
}
