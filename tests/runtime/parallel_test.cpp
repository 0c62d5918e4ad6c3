// Tests of dpgen/parallel.hpp's row strips: for_row_strips and run_by_row_strips give the bits of
// one whole-grid call of the kernel, for periodic and closed grids, one or two output rows per
// input row, widths that differ between input and output, heights that do and do not divide
// into strips, on one thread (strips forced) and on two; every output value is stored once.
#include "dpgen/parallel.hpp"

#include <doctest/doctest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

namespace {

// A kernel of the shape RowStripShape describes: output rows opi * j .. opi * j + opi - 1 read
// input rows j - 1, j, j + 1 (wrapped where periodic; a boundary value at a closed end), with
// columns mixed so that any row or column mix-up changes the bits.
struct TestKernel {
  long in_w, out_w;
  int opi;
  bool periodic;
  void operator()(const std::array<const double*, 2>& in, double* out, int rows) const {
    for (int j = 0; j < rows; ++j) {
      const int jm = j > 0 ? j - 1 : (periodic ? rows - 1 : -1);
      const int jp = j < rows - 1 ? j + 1 : (periodic ? 0 : -1);
      for (int r = 0; r < opi; ++r)
        for (long i = 0; i < out_w; ++i) {
          const double centre = in[0][j * in_w + i % in_w] * (r + 1.5);
          const double below = jm >= 0 ? std::sin(in[1][jm * in_w + (i + 1) % in_w]) : 0.5;
          const double above = jp >= 0 ? in[0][jp * in_w + (3 * i) % in_w] / 3.0 : -0.25;
          out[(static_cast<long>(j) * opi + r) * out_w + i] = centre + below - above * below;
        }
    }
  }
};

std::vector<double> pseudo_random(long n, unsigned seed) {
  std::vector<double> v(static_cast<std::size_t>(n));
  unsigned long long s = seed * 0x9e3779b97f4a7c15ULL + 1;
  for (double& x : v) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    x = static_cast<double>(s >> 11) * 0x1.0p-53 - 0.5;
  }
  return v;
}

// Runs the strips on `threads` threads (forced: split even where one call would do) and
// compares with one whole call, bit for bit; also counts how often each value is stored.
void check_shape(int rows, long in_w, long out_w, int opi, bool periodic, int threads, bool force) {
  CAPTURE(rows);
  CAPTURE(in_w);
  CAPTURE(out_w);
  CAPTURE(opi);
  CAPTURE(periodic);
  CAPTURE(threads);
  const TestKernel kernel{in_w, out_w, opi, periodic};
  const std::vector<double> a = pseudo_random(rows * in_w, 1), b = pseudo_random(rows * in_w, 2);
  const long n_out = static_cast<long>(rows) * opi * out_w;
  std::vector<double> whole(static_cast<std::size_t>(n_out)), strips(whole.size(), NAN);
  kernel({a.data(), b.data()}, whole.data(), rows);
  const dpgen::RowStripShape shape{rows, in_w, out_w, opi, periodic};
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  const bool split =
      dpgen::run_by_row_strips<2>(shape, {a.data(), b.data()}, strips.data(), kernel, force);
  std::vector<int> stored(whole.size(), 0);
  std::vector<int> stores(static_cast<std::size_t>(rows) + 1, 0); // calls, by first row
  const bool split_again = dpgen::for_row_strips<2>(
      shape, {a.data(), b.data()}, kernel,
      [&](Eigen::Index first, Eigen::Index count, const double*) {
        for (Eigen::Index c = first; c < first + count; ++c)
          ++stored[static_cast<std::size_t>(c)]; // each strip its own values: no race
        ++stores[static_cast<std::size_t>(first / (opi * out_w))];
      },
      force);
  omp_set_num_threads(before);
  REQUIRE(split);
  REQUIRE(split_again);
  CHECK(std::memcmp(whole.data(), strips.data(), sizeof(double) * whole.size()) == 0);
  int wrong = 0;
  for (int count : stored)
    wrong += count != 1;
  CHECK(wrong == 0);
  int calls = 0; // the grid was split: a store per strip, at least two
  for (int count : stores)
    calls += count;
  CHECK(calls >= 2);
}

} // namespace

TEST_CASE("row strips give the whole call's bits (forced, one and two threads)") {
  for (bool periodic : {false, true})
    for (int opi : {1, 2})
      for (int rows : {16, 17, 31, 40, 100, 257})
        for (long in_w : {1L, 5L, 64L})
          for (long out_w : {1L, 7L, 64L})
            for (int threads : {1, 2})
              check_shape(rows, in_w, out_w, opi, periodic, threads, /*force=*/true);
}

TEST_CASE("row strips without forcing: wide grids on two threads, a long 1D grid") {
  check_shape(600, 512, 512, 1, true, 2, /*force=*/false);   // 300K values: 2 threads split
  check_shape(300, 512, 1024, 2, false, 2, /*force=*/false); // prolongation-like, 2 rows out
  check_shape(100000, 1, 1, 1, true, 2, /*force=*/false);    // a 1D periodic rollout
}

TEST_CASE("a kernel that runs strips itself: the inner call runs whole, the bits stay") {
  // The strips' buffers are one per thread: a nested call must not use them while its caller's
  // strip is in them. It returns false, and the kernel calls its inner kernel once instead.
  const TestKernel inner{64, 64, 1, false};
  int inner_split = 0;
  const auto outer = [&](const std::array<const double*, 2>& in, double* out, int rows) {
    if (dpgen::run_by_row_strips<2>({rows, 64, 64, 1, false}, in, out, inner, /*force=*/true))
      ++inner_split;
    else
      inner(in, out, rows);
  };
  const std::vector<double> a = pseudo_random(200 * 64, 5), b = pseudo_random(200 * 64, 6);
  std::vector<double> whole(200 * 64), strips(200 * 64, NAN);
  inner({a.data(), b.data()}, whole.data(), 200);
  REQUIRE(dpgen::run_by_row_strips<2>({200, 64, 64, 1, false}, {a.data(), b.data()}, strips.data(),
                                      outer, /*force=*/true));
  CHECK(inner_split == 0);
  CHECK(std::memcmp(whole.data(), strips.data(), sizeof(double) * whole.size()) == 0);
}

TEST_CASE("grids too small or on one thread unforced run whole: nothing is done") {
  const TestKernel kernel{8, 8, 1, true};
  const std::vector<double> a = pseudo_random(15 * 8, 3);
  std::vector<double> out(15 * 8, 7.0);
  // 15 rows: fewer than two strips of 8 rows, even when forced
  CHECK_FALSE(dpgen::run_by_row_strips<2>({15, 8, 8, 1, true}, {a.data(), a.data()}, out.data(),
                                          kernel, /*force=*/true));
  CHECK(out[0] == 7.0);
  const int before = omp_get_max_threads();
  omp_set_num_threads(1); // one thread, not forced: one call does it
  const std::vector<double> big = pseudo_random(512 * 512, 4);
  std::vector<double> big_out(512 * 512, 7.0);
  CHECK_FALSE(dpgen::run_by_row_strips<2>({512, 512, 512, 1, true}, {big.data(), big.data()},
                                          big_out.data(), TestKernel{512, 512, 1, true}));
  omp_set_num_threads(before);
  CHECK(big_out[0] == 7.0);
}
