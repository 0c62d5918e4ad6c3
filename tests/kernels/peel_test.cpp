// The forward forms of peel_kernels.cpp, whose loops are split into edge and branch-free
// interior iterations (loop_plan.cpp: peel_forward): <kernel>_parallel_forward
// must give the kernel's values bit for bit, on 1 and 2 threads, at sizes with no interior
// (1, 2, 3 cells: every iteration an edge, some conditions holding at both ends at once),
// small interiors and one above the threading threshold; the tangent (printed the same way)
// must reproduce the outputs bit for bit and agree with finite differences and the adjoint
// (support/adjoint_check.hpp).
#include "support/adjoint_check.hpp"

#include "peel_kernels_adjoint.hpp"
#include "peel_kernels_kernels.hpp"
#include "peel_kernels_tangent.hpp"

#include <doctest/doctest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <tuple>
#include <vector>

namespace {

std::vector<double> values(size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  std::vector<double> v(n);
  for (auto& x : v)
    x = dist(gen);
  return v;
}

// `kernel` and `split` write the same bits into outputs prefilled with NaN (an element one
// writes and the other does not shows), on 1 and 2 threads.
void same_bits(size_t out_size, const std::function<void(double*)>& kernel,
               const std::function<void(double*)>& split) {
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    omp_set_num_threads(threads);
    std::vector<double> a(out_size, std::nan("")), b(out_size, std::nan(""));
    kernel(a.data());
    split(b.data());
    CHECK(std::memcmp(a.data(), b.data(), sizeof(double) * out_size) == 0);
  }
}

const int kSizes[] = {1, 2, 3, 4, 5, 8, 33, 9001}; // 9001: above 8192, on every thread

} // namespace

TEST_CASE("peeled forward: 1D kernels bit for bit at every size") {
  for (int n : kSizes) {
    CAPTURE(n);
    const auto a = values(size_t(n), 1);
    same_bits(
        size_t(n), [&](double* o) { peel_wrap_c89(a.data(), o, n); },
        [&](double* o) { peel_wrap_c89_parallel_forward(a.data(), o, n); });
    same_bits(
        size_t(n), [&](double* o) { peel_guarded(a.data(), o, n, 0.3); },
        [&](double* o) { peel_guarded_parallel_forward(a.data(), o, n, 0.3); });
    if (n >= 2) { // (its wraps i + n - 2 need two cells)
      same_bits(
          size_t(n), [&](double* o) { peel_wide_wrap(a.data(), o, n); },
          [&](double* o) { peel_wide_wrap_parallel_forward(a.data(), o, n); });
    }
    same_bits(
        size_t(n), [&](double* o) { peel_descending(a.data(), o, n); },
        [&](double* o) { peel_descending_parallel_forward(a.data(), o, n); });
    same_bits(
        size_t(n), [&](double* o) { peel_clamped(a.data(), o, n); },
        [&](double* o) { peel_clamped_parallel_forward(a.data(), o, n); });
    same_bits(
        size_t(n), [&](double* o) { peel_coef(a.data(), o, n, 0.3); },
        [&](double* o) { peel_coef_parallel_forward(a.data(), o, n, 0.3); });
    same_bits(
        size_t(n), [&](double* o) { peel_offsets(a.data(), o, n); },
        [&](double* o) { peel_offsets_parallel_forward(a.data(), o, n); });
    // (twice[n] then sum[1] in one buffer; the sum serial, in the kernel's order)
    same_bits(
        size_t(n) + 1, [&](double* o) { peel_trapezoid(a.data(), o, o + n, n, 0.1); },
        [&](double* o) { peel_trapezoid_parallel_forward(a.data(), o, o + n, n, 0.1); });
  }
}

TEST_CASE("peeled forward: descending outer loops (parallel and serial) and a triangle") {
  for (int n : {1, 2, 3, 5, 100}) {
    CAPTURE(n);
    const size_t cells = size_t(n) * size_t(n);
    const auto a = values(cells, 5);
    same_bits(
        cells, [&](double* o) { peel_triangle(a.data(), o, n); },
        [&](double* o) { peel_triangle_parallel_forward(a.data(), o, n); });
    for (int ny : {1, 2, 3, 97}) {
      CAPTURE(ny);
      const size_t grid = size_t(n) * size_t(ny);
      const auto b = values(grid, 6);
      same_bits(
          grid, [&](double* o) { peel_descending_rows(b.data(), o, n, ny); },
          [&](double* o) { peel_descending_rows_parallel_forward(b.data(), o, n, ny); });
      same_bits(
          size_t(n), [&](double* o) { peel_column_sums(b.data(), o, n, ny); },
          [&](double* o) { peel_column_sums_parallel_forward(b.data(), o, n, ny); });
    }
  }
}

TEST_CASE("peeled forward: three loops, the middle one not split") {
  for (auto [nx, ny, nz] :
       {std::tuple{1, 1, 1}, {2, 1, 3}, {1, 3, 2}, {3, 2, 2}, {5, 4, 3}, {40, 20, 12}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    const size_t cells = size_t(nx) * size_t(ny) * size_t(nz);
    const auto a = values(cells, 4);
    same_bits(
        cells, [&](double* o) { peel_box3d(a.data(), o, nx, ny, nz); },
        [&](double* o) { peel_box3d_parallel_forward(a.data(), o, nx, ny, nz); });
  }
}

TEST_CASE("peeled forward: 2D kernels, the inner loop split in interior rows") {
  for (auto [nx, ny] : {std::pair{1, 1}, {1, 4}, {4, 1}, {2, 3}, {3, 2}, {5, 7}, {130, 90}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    const auto a = values(cells, 2), k = values(cells, 3);
    same_bits(
        cells, [&](double* o) { peel_torus2d(a.data(), k.data(), o, nx, ny); },
        [&](double* o) { peel_torus2d_parallel_forward(a.data(), k.data(), o, nx, ny); });
    same_bits(
        cells, [&](double* o) { peel_walls2d(a.data(), o, nx, ny); },
        [&](double* o) { peel_walls2d_parallel_forward(a.data(), o, nx, ny); });
  }
}

namespace {

// One input, one output of n cells: adjoint, tangent (outputs bit for bit) and checked entry.
template <typename Fwd, typename Adj, typename Chk, typename Tan>
void check_1d(int n, Fwd fwd, Adj adj, Chk chk, Tan tan) {
  dpgen_test::Problem<double> p;
  p.in_sizes = {size_t(n)};
  p.out_sizes = {size_t(n)};
  p.forward = [&](auto in, auto out) { fwd(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto a, auto seed) { adj(in[0], a[0], seed[0], n); };
  p.checked = [&](auto in, auto a, auto seed, auto in_n, auto out_n) {
    chk(in[0], in_n[0], a[0], in_n[0], seed[0], out_n[0], n);
  };
  p.tangent = [&](auto in, auto dir, auto out, auto outd) {
    tan(in[0], dir[0], out[0], outd[0], n);
  };
  dpgen_test::check_adjoint(p);
}

using dpgen_test::check_one_to_one;

} // namespace

TEST_CASE("peeled tangents: outputs bit for bit, J v against differences and the adjoint") {
  for (int n : {1, 2, 3, 4, 6, 17}) {
    CAPTURE(n);
    check_1d(n, peel_wrap_c89, peel_wrap_c89_adjoint, peel_wrap_c89_adjoint_checked,
             peel_wrap_c89_tangent);
    check_1d(
        n, [](auto a, auto o, int m) { peel_guarded(a, o, m, 0.7); },
        [](auto a, auto aa, auto s, int m) { peel_guarded_adjoint(a, aa, s, m, 0.7); },
        [](auto a, auto an, auto aa, auto aan, auto s, auto sn, int m) {
          peel_guarded_adjoint_checked(a, an, aa, aan, s, sn, m, 0.7);
        },
        [](auto a, auto d, auto o, auto od, int m) { peel_guarded_tangent(a, d, o, od, m, 0.7); });
    if (n >= 2)
      check_1d(n, peel_wide_wrap, peel_wide_wrap_adjoint, peel_wide_wrap_adjoint_checked,
               peel_wide_wrap_tangent);
    check_1d(n, peel_descending, peel_descending_adjoint, peel_descending_adjoint_checked,
             peel_descending_tangent);
    check_1d(n, peel_clamped, peel_clamped_adjoint, peel_clamped_adjoint_checked,
             peel_clamped_tangent);
    check_1d(n, peel_offsets, peel_offsets_adjoint, peel_offsets_adjoint_checked,
             peel_offsets_tangent);
    check_1d(
        n, [](auto a, auto o, int m) { peel_coef(a, o, m, 0.4); },
        [](auto a, auto aa, auto s, int m) { peel_coef_adjoint(a, aa, s, m, 0.4); },
        [](auto a, auto an, auto aa, auto aan, auto s, auto sn, int m) {
          peel_coef_adjoint_checked(a, an, aa, aan, s, sn, m, 0.4);
        },
        [](auto a, auto d, auto o, auto od, int m) { peel_coef_tangent(a, d, o, od, m, 0.4); });
  }
  for (int n : {1, 2, 3, 7}) { // two outputs, the second a serial sum
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), 1};
    p.forward = [&](auto in, auto out) { peel_trapezoid(in[0], out[0], out[1], n, 0.3); };
    p.adjoint = [&](auto in, auto a, auto seed) {
      peel_trapezoid_adjoint(in[0], a[0], seed[0], seed[1], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      peel_trapezoid_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {3, 2}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    check_one_to_one(
        cells, cells, [&](auto a, auto o) { peel_descending_rows(a, o, nx, ny); },
        [&](auto a, auto aa, auto s) { peel_descending_rows_adjoint(a, aa, s, nx, ny); },
        [&](auto a, auto d, auto o, auto od) {
          peel_descending_rows_tangent(a, d, o, od, nx, ny);
        });
    check_one_to_one(
        cells, size_t(nx), [&](auto a, auto o) { peel_column_sums(a, o, nx, ny); },
        [&](auto a, auto aa, auto s) { peel_column_sums_adjoint(a, aa, s, nx, ny); },
        [&](auto a, auto d, auto o, auto od) { peel_column_sums_tangent(a, d, o, od, nx, ny); });
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells, cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { peel_torus2d(in[0], in[1], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto a, auto seed) {
      peel_torus2d_adjoint(in[0], a[0], in[1], a[1], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      peel_torus2d_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
    dpgen_test::Problem<double> w;
    w.in_sizes = {cells};
    w.out_sizes = {cells};
    w.forward = [&](auto in, auto out) { peel_walls2d(in[0], out[0], nx, ny); };
    w.adjoint = [&](auto in, auto a, auto seed) {
      peel_walls2d_adjoint(in[0], a[0], seed[0], nx, ny);
    };
    w.tangent = [&](auto in, auto dir, auto out, auto outd) {
      peel_walls2d_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(w);
  }
}

// The adjoint's edge rows (CellLoop::row_terms): the west layer `i < m` stays checked in an edge
// row's cells within the interior's range of i, [2, nx - 2): m up to 2 applies to none of
// them, m = nx / 2 to part of the range (a row split by the check), m = nx to all of it.
TEST_CASE("adjoint edge rows: a term the interior's range does not decide is still checked") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {5, 4}, {9, 6}, {12, 7}}) {
    for (int m : {0, 1, 3, nx / 2, nx}) {
      CAPTURE(nx);
      CAPTURE(ny);
      CAPTURE(m);
      const size_t cells = size_t(nx) * size_t(ny);
      check_one_to_one(
          cells, cells, [&](auto a, auto o) { peel_edge_rows(a, o, nx, ny, m); },
          [&](auto a, auto aa, auto s) { peel_edge_rows_adjoint(a, aa, s, nx, ny, m); },
          [&](auto a, auto d, auto o, auto od) { peel_edge_rows_tangent(a, d, o, od, nx, ny, m); });
    }
  }
}

TEST_CASE("adjoint edge rows: counters named row and col") {
  for (auto [nrows, ncols] : {std::pair{1, 1}, {3, 2}, {6, 9}}) {
    CAPTURE(nrows);
    CAPTURE(ncols);
    const size_t cells = size_t(nrows) * size_t(ncols);
    check_one_to_one(
        cells, cells, [&](auto a, auto o) { peel_row_col(a, o, nrows, ncols); },
        [&](auto a, auto aa, auto s) { peel_row_col_adjoint(a, aa, s, nrows, ncols); },
        [&](auto a, auto d, auto o, auto od) { peel_row_col_tangent(a, d, o, od, nrows, ncols); });
  }
}

// Two inputs with near cell boxes run in one adjoint loop over the box around both
// (loop_plan.cpp: near_boxes; tests/passes/plan.cpp checks that these two fuse); with one
// adjoint null, each runs its own loop. Checked against finite differences and the tangent at
// sizes where one box is empty and the other not, and above the threading threshold. For these
// kernels the loop of one input alone gives the fused loop's bits. (Not for every kernel: a
// cell in an interior row of its input's own loop may be in an edge row of the fused one,
// where a factored sum of both signs, c * (a - b), is summed term by term, c * a + -(c * b).)
template <typename Fwd, typename Adj, typename Tan>
void check_two_inputs(size_t n, Fwd forward, Adj adjoint, Tan tangent) {
  dpgen_test::Problem<double> p;
  p.in_sizes = {n, n};
  p.out_sizes = {n};
  p.forward = [&](auto in, auto out) { forward(in[0], in[1], out[0]); };
  p.adjoint = [&](auto in, auto adj, auto seed) { adjoint(in[0], adj[0], in[1], adj[1], seed[0]); };
  p.tangent = [&](auto in, auto dir, auto out, auto outd) {
    tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0]);
  };
  dpgen_test::check_adjoint(p);
  if (n == 0)
    return; // (empty vectors: null data, which is a null adjoint, and memcmp of null)
  const auto a = values(n, 7), b = values(n, 8), seed = values(n, 9);
  const int max_threads = omp_get_max_threads();
  // (A cell outside an input's box that the fused loop wrote with an empty sum would not show:
  // sums start at -0.0, and x + -0.0 is x for every x. A term applied there would.)
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    omp_set_num_threads(threads);
    std::vector<double> fa = values(n, 10), fb = values(n, 11), la = fa, lb = fb;
    adjoint(a.data(), fa.data(), b.data(), fb.data(), seed.data());
    adjoint(a.data(), la.data(), b.data(), nullptr, seed.data());
    adjoint(a.data(), nullptr, b.data(), lb.data(), seed.data());
    CHECK(std::memcmp(fa.data(), la.data(), n * sizeof(double)) == 0);
    CHECK(std::memcmp(fb.data(), lb.data(), n * sizeof(double)) == 0);
  }
  omp_set_num_threads(max_threads);
}

TEST_CASE("adjoint of two inputs with near cell boxes: 1D") {
  for (int n : {0, 1, 2, 3, 4, 5, 6, 7, 9, 12, 9001}) { // (9001: above 8192, as kSizes)
    CAPTURE(n);
    check_two_inputs(
        size_t(n), [&](auto a, auto b, auto o) { peel_near_boxes_1d(a, b, o, n); },
        [&](auto a, auto aa, auto b, auto ba, auto s) {
          peel_near_boxes_1d_adjoint(a, aa, b, ba, s, n);
        },
        [&](auto a, auto ad, auto b, auto bd, auto o, auto od) {
          peel_near_boxes_1d_tangent(a, ad, b, bd, o, od, n);
        });
  }
}

TEST_CASE("adjoint of two inputs with near cell boxes: 2D") {
  for (auto [nx, ny] : {std::pair{1, 1}, {1, 4}, {4, 1}, {2, 2}, {3, 5}, {7, 4}, {130, 70}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const double h = 0.5;
    check_two_inputs(
        size_t(nx) * size_t(ny),
        [&](auto u, auto v, auto o) { peel_near_boxes_mac(u, v, o, nx, ny, h); },
        [&](auto u, auto ua, auto v, auto va, auto s) {
          peel_near_boxes_mac_adjoint(u, ua, v, va, s, nx, ny, h);
        },
        [&](auto u, auto ud, auto v, auto vd, auto o, auto od) {
          peel_near_boxes_mac_tangent(u, ud, v, vd, o, od, nx, ny, h);
        });
  }
}
