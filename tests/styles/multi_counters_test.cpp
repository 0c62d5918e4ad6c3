// multi_counters (tests/styles/): loops with companion counters and strided
// loops counting down; each adjoint and tangent against the checker's
// differences, and the mirror's values by hand.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "multi_counters_adjoint.hpp"
#include "multi_counters_kernels.hpp"
#include "multi_counters_tangent.hpp"

#include <tuple>

using dpgen_test::check_one_to_one;

TEST_CASE("styles: mirror_product, reverse_blend, postdec_pair, offset_weights") {
  for (int n : {0, 1, 2, 3, 8, 11}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        N, N, [&](auto a, auto b) { mirror_product(a, b, n); },
        [&](auto a, auto adj, auto seed) { mirror_product_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { mirror_product_tangent(a, d, b, bd, n); });
    check_one_to_one(
        N, N, [&](auto a, auto b) { reverse_blend(a, b, n); },
        [&](auto a, auto adj, auto seed) { reverse_blend_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { reverse_blend_tangent(a, d, b, bd, n); });
    const unsigned un = unsigned(n);
    check_one_to_one(
        N, N, [&](auto a, auto b) { unsigned_mirror(a, b, un); },
        [&](auto a, auto adj, auto seed) { unsigned_mirror_adjoint(a, adj, seed, un); },
        [&](auto a, auto d, auto b, auto bd) { unsigned_mirror_tangent(a, d, b, bd, un); });
    check_one_to_one(
        N, N, [&](auto a, auto c) { postdec_pair(a, c, n); },
        [&](auto a, auto adj, auto seed) { postdec_pair_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto c, auto cd) { postdec_pair_tangent(a, d, c, cd, n); });
    check_one_to_one(
        N, N, [&](auto u, auto o) { offset_weights(u, o, n); },
        [&](auto u, auto adj, auto seed) { offset_weights_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto o, auto od) { offset_weights_tangent(u, d, o, od, n); });
  }
  // b[i] = a[n - 1 - i] a[i], and its adjoint a_adj[i] = 2 a[n - 1 - i] b_adj[i] for the
  // seed's symmetric part: by hand on n = 3
  const double a[3] = {1.0, 2.0, 5.0}, seed[3] = {1.0, 10.0, 100.0};
  double b[3] = {0, 0, 0}, adj[3] = {0, 0, 0};
  mirror_product(a, b, 3);
  mirror_product_adjoint(a, adj, seed, 3);
  CHECK(b[0] == 5.0);
  CHECK(b[1] == 4.0);
  CHECK(b[2] == 5.0);
  CHECK(adj[0] == doctest::Approx(5.0 * 1.0 + 5.0 * 100.0)); // from b[0] and b[2]
  CHECK(adj[1] == doctest::Approx(2.0 * 2.0 * 10.0));
  CHECK(adj[2] == doctest::Approx(1.0 * 1.0 + 1.0 * 100.0));
}

TEST_CASE("styles: complex_magnitude") {
  for (int n : {0, 1, 2, 7}) {
    CAPTURE(n);
    check_one_to_one(
        2 * size_t(n), size_t(n), [&](auto z, auto m) { complex_magnitude(z, m, n); },
        [&](auto z, auto adj, auto seed) { complex_magnitude_adjoint(z, adj, seed, n); },
        [&](auto z, auto d, auto m, auto md) { complex_magnitude_tangent(z, d, m, md, n); });
  }
}

TEST_CASE("styles: laplace_flat_index, rb_down_sweep") {
  for (auto [nx, ny] : {std::tuple{3, 3}, {4, 5}, {7, 6}, {2, 8}, {9, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    check_one_to_one(
        N, N, [&](auto u, auto l) { laplace_flat_index(u, l, nx, ny, 0.5); },
        [&](auto u, auto adj, auto seed) { laplace_flat_index_adjoint(u, adj, seed, nx, ny, 0.5); },
        [&](auto u, auto d, auto l, auto ld) {
          laplace_flat_index_tangent(u, d, l, ld, nx, ny, 0.5);
        });
    check_one_to_one(
        N, N, [&](auto u, auto v) { rb_down_sweep(u, v, nx, ny); },
        [&](auto u, auto adj, auto seed) { rb_down_sweep_adjoint(u, adj, seed, nx, ny); },
        [&](auto u, auto d, auto v, auto vd) { rb_down_sweep_tangent(u, d, v, vd, nx, ny); });
  }
}

TEST_CASE("styles: down_by_two, unsigned_down_by_three") {
  for (long long n : {0, 1, 2, 5, 6, 13}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        N, N, [&](auto a, auto e) { down_by_two(a, e, n); },
        [&](auto a, auto adj, auto seed) { down_by_two_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto e, auto ed) { down_by_two_tangent(a, d, e, ed, n); });
    const unsigned m = unsigned(n);
    check_one_to_one(
        N + 1, N + 1, [&](auto a, auto e) { unsigned_down_by_three(a, e, m); },
        [&](auto a, auto adj, auto seed) { unsigned_down_by_three_adjoint(a, adj, seed, m); },
        [&](auto a, auto d, auto e, auto ed) { unsigned_down_by_three_tangent(a, d, e, ed, m); });
  }
}

TEST_CASE("styles: strided_unsigned_scatter (a scatter adjoint over an empty strided range)") {
  for (std::size_t n : {0, 5, 10, 11, 14, 23}) {
    CAPTURE(n);
    check_one_to_one(
        n, n, [&](auto a, auto e) { strided_unsigned_scatter(a, e, n); },
        [&](auto a, auto adj, auto seed) { strided_unsigned_scatter_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto e, auto ed) { strided_unsigned_scatter_tangent(a, d, e, ed, n); });
  }
}
