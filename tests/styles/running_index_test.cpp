// running_index (tests/styles/): running indices; each adjoint and tangent
// against the checker's differences, values by hand, and the parallel
// forwards bit for bit against the kernels at sizes where they run on
// every thread.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "running_index_adjoint.hpp"
#include "running_index_kernels.hpp"
#include "running_index_tangent.hpp"
#include "same_bits.hpp"

using dpgen_test::check_one_to_one;

TEST_CASE("styles: ghost_rows, c89_flat") {
  for (int nx : {0, 1, 2, 3, 5})
    for (int ny : {0, 1, 2, 4}) {
      CAPTURE(nx);
      CAPTURE(ny);
      const size_t N = size_t(nx * ny);
      if (nx >= 2 && ny >= 2)
        check_one_to_one(
            N, N, [&](auto a, auto b) { ghost_rows(a, b, nx, ny); },
            [&](auto a, auto adj, auto seed) { ghost_rows_adjoint(a, adj, seed, nx, ny); },
            [&](auto a, auto d, auto b, auto bd) { ghost_rows_tangent(a, d, b, bd, nx, ny); });
      check_one_to_one(
          N, N, [&](auto a, auto b) { c89_flat(a, b, nx, ny); },
          [&](auto a, auto adj, auto seed) { c89_flat_adjoint(a, adj, seed, nx, ny); },
          [&](auto a, auto d, auto b, auto bd) { c89_flat_tangent(a, d, b, bd, nx, ny); });
    }
  // by hand: the interior cell (1, 1) of a 3 x 3 grid
  double a[9], b[9];
  for (int k = 0; k < 9; ++k) {
    a[k] = k + 1.0;
    b[k] = -7.0;
  }
  ghost_rows(a, b, 3, 3);
  CHECK(b[4] == 4.0 + 6.0 - 10.0 + 2.0 * 8.0);
  CHECK(b[3] == -7.0);
  // both on every thread (1000 x 12 cells)
  dpgen_test::same_bits(
      12000, 12000, [](auto a, auto b) { ghost_rows(a, b, 1000, 12); },
      [](auto a, auto b) { ghost_rows_parallel_forward(a, b, 1000, 12); });
  dpgen_test::same_bits(
      12000, 12000, [](auto a, auto b) { c89_flat(a, b, 1000, 12); },
      [](auto a, auto b) { c89_flat_parallel_forward(a, b, 1000, 12); });
}

TEST_CASE("styles: pair_products, reverse_fill, step_first, pair_sums, tail_after") {
  for (int n : {0, 1, 2, 3, 8, 11}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        2 * N + 1, N, [&](auto a, auto b) { pair_products(a, b, n); },
        [&](auto a, auto adj, auto seed) { pair_products_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { pair_products_tangent(a, d, b, bd, n); });
    check_one_to_one(
        N, N, [&](auto a, auto b) { reverse_fill(a, b, n); },
        [&](auto a, auto adj, auto seed) { reverse_fill_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { reverse_fill_tangent(a, d, b, bd, n); });
    check_one_to_one(
        N, N, [&](auto a, auto b) { step_first(a, b, N); },
        [&](auto a, auto adj, auto seed) { step_first_adjoint(a, adj, seed, N); },
        [&](auto a, auto d, auto b, auto bd) { step_first_tangent(a, d, b, bd, N); });
    check_one_to_one(
        N, N / 2, [&](auto a, auto b) { pair_sums(a, b, n); },
        [&](auto a, auto adj, auto seed) { pair_sums_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { pair_sums_tangent(a, d, b, bd, n); });
    check_one_to_one(
        N + 1, N + 1, [&](auto a, auto b) { tail_after(a, b, n); },
        [&](auto a, auto adj, auto seed) { tail_after_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { tail_after_tangent(a, d, b, bd, n); });
  }
  const double a[4] = {1.0, 2.0, 3.0, 4.0};
  double b[4] = {0.0, 0.0, 0.0, 0.0};
  reverse_fill(a, b, 4);
  CHECK(b[0] == 4.0 * 1.0);
  CHECK(b[3] == 1.0 * 4.0);
  tail_after(a, b, 3);
  CHECK(b[2] == 3.0 * 4.0);
  CHECK(b[3] == 16.0);
  dpgen_test::same_bits(
      20001, 10000, [](auto a, auto b) { pair_products(a, b, 10000); },
      [](auto a, auto b) { pair_products_parallel_forward(a, b, 10000); });
  dpgen_test::same_bits(
      10000, 10000, [](auto a, auto b) { reverse_fill(a, b, 10000); },
      [](auto a, auto b) { reverse_fill_parallel_forward(a, b, 10000); });
}

TEST_CASE("styles: flat3d, rgb_scale") {
  for (int nx : {1, 2, 3})
    for (int ny : {0, 1, 2})
      for (int nz : {1, 3}) {
        CAPTURE(nx);
        CAPTURE(ny);
        CAPTURE(nz);
        const size_t N = size_t(nx * ny * nz);
        check_one_to_one(
            N, N, [&](auto a, auto b) { flat3d(a, b, nx, ny, nz); },
            [&](auto a, auto adj, auto seed) { flat3d_adjoint(a, adj, seed, nx, ny, nz); },
            [&](auto a, auto d, auto b, auto bd) { flat3d_tangent(a, d, b, bd, nx, ny, nz); });
      }
  for (int np : {0, 1, 4}) {
    CAPTURE(np);
    const size_t N = size_t(3 * np);
    check_one_to_one(
        N, N, [&](auto a, auto b) { rgb_scale(a, b, np); },
        [&](auto a, auto adj, auto seed) { rgb_scale_adjoint(a, adj, seed, np); },
        [&](auto a, auto d, auto b, auto bd) { rgb_scale_tangent(a, d, b, bd, np); });
  }
  dpgen_test::same_bits(
      20 * 30 * 20, 20 * 30 * 20, [](auto a, auto b) { flat3d(a, b, 20, 30, 20); },
      [](auto a, auto b) { flat3d_parallel_forward(a, b, 20, 30, 20); });
}

TEST_CASE("styles: pack_squares, unpack_pairs, fill_backwards") {
  for (int nx : {0, 1, 3})
    for (int ny : {0, 2, 3}) {
      CAPTURE(nx);
      CAPTURE(ny);
      const size_t N = size_t(nx * ny);
      check_one_to_one(
          N, N, [&](auto a, auto b) { pack_squares(a, b, nx, ny); },
          [&](auto a, auto adj, auto seed) { pack_squares_adjoint(a, adj, seed, nx, ny); },
          [&](auto a, auto d, auto b, auto bd) { pack_squares_tangent(a, d, b, bd, nx, ny); });
    }
  for (int n : {0, 1, 2, 9}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        2 * N, N, [&](auto a, auto b) { unpack_pairs(a, b, n); },
        [&](auto a, auto adj, auto seed) { unpack_pairs_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { unpack_pairs_tangent(a, d, b, bd, n); });
    check_one_to_one(
        N, N, [&](auto a, auto b) { fill_backwards(a, b, n); },
        [&](auto a, auto adj, auto seed) { fill_backwards_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { fill_backwards_tangent(a, d, b, bd, n); });
  }
  // by hand: a[0..3] = 1, 2, 3, 4 unpacked in pairs; reversed
  const double a[4] = {1.0, 2.0, 3.0, 4.0};
  double b[4] = {0.0, 0.0, 0.0, 0.0};
  unpack_pairs(a, b, 2);
  CHECK(b[0] == 2.0 + 2.0 * 1.0);
  CHECK(b[1] == 6.0 + 4.0 * 2.0);
  fill_backwards(a, b, 4);
  CHECK(b[3] == 0.0);
  CHECK(b[0] == 4.0 - 16.0);
  dpgen_test::same_bits(
      100 * 100, 100 * 100, [](auto a, auto b) { pack_squares(a, b, 100, 100); },
      [](auto a, auto b) { pack_squares_parallel_forward(a, b, 100, 100); });
}

TEST_CASE("styles: row_pointer_index, strided_before") {
  for (int nx : {2, 3, 5})
    for (int ny : {2, 4}) {
      CAPTURE(nx);
      CAPTURE(ny);
      const size_t N = size_t(nx * ny);
      check_one_to_one(
          N, N, [&](auto a, auto b) { row_pointer_index(a, b, nx, ny); },
          [&](auto a, auto adj, auto seed) { row_pointer_index_adjoint(a, adj, seed, nx, ny); },
          [&](auto a, auto d, auto b, auto bd) { row_pointer_index_tangent(a, d, b, bd, nx, ny); });
    }
  for (int n : {0, 1, 2, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        2 * N, N, [&](auto a, auto b) { strided_before(a, b, n); },
        [&](auto a, auto adj, auto seed) { strided_before_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { strided_before_tangent(a, d, b, bd, n); });
  }
  // by hand: b[2] of n = 3 reads a[4] and a[1]; b[1] is skipped
  const double a[6] = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  double b[3] = {7.0, 7.0, 7.0};
  strided_before(a, b, 3);
  CHECK(b[0] == 1.0 * 6.0);
  CHECK(b[1] == 0.0);
  CHECK(b[2] == 5.0 * 2.0);
  dpgen_test::same_bits(
      100 * 100, 100 * 100, [](auto a, auto b) { row_pointer_index(a, b, 100, 100); },
      [](auto a, auto b) { row_pointer_index_parallel_forward(a, b, 100, 100); });
}

TEST_CASE("styles: tail_after_nest") {
  for (int nx : {0, 1, 2, 4})
    for (int ny : {0, 1, 3}) {
      CAPTURE(nx);
      CAPTURE(ny);
      const size_t N = size_t(nx * ny + 1);
      check_one_to_one(
          N, N, [&](auto a, auto b) { tail_after_nest(a, b, nx, ny); },
          [&](auto a, auto adj, auto seed) { tail_after_nest_adjoint(a, adj, seed, nx, ny); },
          [&](auto a, auto d, auto b, auto bd) { tail_after_nest_tangent(a, d, b, bd, nx, ny); });
    }
  // by hand: 3 x 2, the last cell b[6] = a[6] * a[0]
  double a[7], b[7];
  for (int k = 0; k < 7; ++k) {
    a[k] = k + 1.0;
    b[k] = -1.0;
  }
  tail_after_nest(a, b, 3, 2);
  CHECK(b[6] == 7.0);
  CHECK(b[2] == -1.0);
  CHECK(b[4] == 5.0 * 6.0);
}
