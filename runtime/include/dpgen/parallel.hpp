// Both cores for code that was written serial: a 2D row-major stencil kernel run on horizontal
// strips of its grid in parallel (run_by_row_strips), and the vector loops of the solvers
// (fused updates, reductions in a fixed order) with OpenMP. Without OpenMP, or on one thread,
// everything runs serially; results depend on the number of threads only through the order of
// the sums in reductions, never from run to run.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace dpgen {

namespace detail {

inline int max_threads() {
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

// Below this many values a loop stays on one thread: a pass over 64K doubles takes tens of us,
// a parallel region a few (and far more on a machine whose cores are busy with other work).
constexpr Eigen::Index kParallelValues = 65536;

} // namespace detail

/// The shape of a kernel for run_by_row_strips: `rows` input rows of `in_width` values (every
/// input array), `out_per_in * rows` output rows of `out_width` values; output rows
/// out_per_in * j .. out_per_in * (j + 1) - 1 depend only on input rows j - 1, j, j + 1 (a
/// stencil of radius 1 along y; anything along x) and on whether j is the first or last row.
/// `periodic`: the first and last input rows are neighbours.
struct RowStripShape {
  int rows = 0;
  Eigen::Index in_width = 0;
  Eigen::Index out_width = 0;
  int out_per_in = 1;
  bool periodic = false;
};

/// Runs `kernel(inputs, out, strip_rows)` (inputs: std::array<const double*, N> of the strip's
/// input rows, out: its output rows, strip_rows: how many input rows it has) on horizontal
/// strips of the grid so that the output equals kernel(inputs, out, shape.rows) on the whole
/// grid, for any kernel of the shape described above (`out` must not overlap an input). A strip
/// gets one extra input row on each side (its neighbours' rows, or the wrapped row on a
/// periodic grid), whose output rows are not kept: the kernel treats them as boundary rows. Strips
/// run on every thread in two passes (even strips, then odd ones: a strip's call overwrites the
/// edge output rows of its neighbours, which an odd strip saves and puts back); periodic end strips
/// work on copies. `force_strips`: split even where one call would do (one thread, a small grid),
/// to check that a kernel has the shape, bit for bit. Returns false (and does nothing) when the
/// grid is too small to split: call the kernel once.
template <std::size_t N, typename Kernel>
bool run_by_row_strips(const RowStripShape& shape, const std::array<const double*, N>& inputs,
                       double* out, Kernel&& kernel, bool force_strips = false) {
  const int threads = detail::max_threads();
  const int rows = shape.rows;
  const Eigen::Index in_w = shape.in_width, out_w = shape.out_width;
  const int opi = shape.out_per_in;
  // Even and odd strips of at least 8 rows, 2 per thread and pass.
  const int wanted = 4 * threads;
  const int strips = std::min(wanted, rows / 8) / 2 * 2;
  const Eigen::Index values = Eigen::Index(rows) * std::max(in_w, opi * out_w);
  if (strips < 4 || (!force_strips && (threads < 2 || values < detail::kParallelValues)))
    return false;
  const auto strip_begin = [&](int s) { return static_cast<int>(Eigen::Index(rows) * s / strips); };
  const Eigen::Index out_row = opi * out_w; // output values per input row

  // A strip [a, b) whose halo rows lie inside the grid: the kernel reads and writes in place.
  // Returns the output rows it overwrote outside the strip (none at a closed end).
  const auto run_in_place = [&](int a, int b, double* saved) {
    const int below = a > 0 ? 1 : 0, above = b < rows ? 1 : 0;
    if (saved != nullptr) { // keep the neighbours' rows it will overwrite
      if (below)
        std::memcpy(saved, out + (a - 1) * out_row, sizeof(double) * out_row);
      if (above)
        std::memcpy(saved + out_row, out + b * out_row, sizeof(double) * out_row);
    }
    std::array<const double*, N> in;
    for (std::size_t i = 0; i < N; ++i)
      in[i] = inputs[i] + (a - below) * in_w;
    kernel(in, out + (a - below) * out_row, b - a + below + above);
    if (saved != nullptr) {
      if (below)
        std::memcpy(out + (a - 1) * out_row, saved, sizeof(double) * out_row);
      if (above)
        std::memcpy(out + b * out_row, saved + out_row, sizeof(double) * out_row);
    }
  };
  // A periodic end strip: its wrapped halo row is copied next to it, and so is its output.
  const auto run_on_copies = [&](int a, int b, std::vector<double>& buffer) {
    const int n = b - a + 2;
    buffer.resize(static_cast<std::size_t>(N * n * in_w + n * out_row));
    std::array<const double*, N> in;
    for (std::size_t i = 0; i < N; ++i) {
      double* copy = buffer.data() + i * n * in_w;
      const int below = a > 0 ? a - 1 : rows - 1, above = b < rows ? b : 0;
      std::memcpy(copy, inputs[i] + below * in_w, sizeof(double) * in_w);
      std::memcpy(copy + in_w, inputs[i] + a * in_w, sizeof(double) * (b - a) * in_w);
      std::memcpy(copy + (n - 1) * in_w, inputs[i] + above * in_w, sizeof(double) * in_w);
      in[i] = copy;
    }
    double* result = buffer.data() + N * n * in_w;
    kernel(in, result, n);
    std::memcpy(out + a * out_row, result + out_row, sizeof(double) * (b - a) * out_row);
  };
  const auto run_strip = [&](int s, std::vector<double>& buffer) {
    const int a = strip_begin(s), b = strip_begin(s + 1);
    if (shape.periodic && (s == 0 || s == strips - 1))
      run_on_copies(a, b, buffer);
    else if (s % 2 == 0)
      run_in_place(a, b, nullptr); // the odd strips' rows it overwrites are computed later
    else {
      buffer.resize(static_cast<std::size_t>(2 * out_row));
      run_in_place(a, b, buffer.data());
    }
  };
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
  {
    // per thread: one strip's copies, or two saved rows; kept by the thread (OpenMP's threads
    // live on), so that a call allocates nothing once the sizes have been seen
    thread_local std::vector<double> buffer;
    for (int parity = 0; parity < 2; ++parity) {
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
      for (int half = 0; half < strips / 2; ++half)
        run_strip(2 * half + parity, buffer);
    }
  }
  return true;
}

// Vector loops on both cores. Each is one pass over its operands; reductions add per-thread
// partial sums in thread order (static schedule), so a result never changes from run to run.

/// Calls body(lo, hi) on contiguous chunks [lo, hi) of [0, n), one per thread (all of it on one
/// thread below kParallelValues), and returns the sum of what the calls return, in chunk order.
template <typename Body> double parallel_chunks(Eigen::Index n, Body&& body) {
  constexpr int kMaxThreads = 64;
  const int threads =
      std::min(n >= detail::kParallelValues ? detail::max_threads() : 1, kMaxThreads);
  if (threads == 1)
    return body(Eigen::Index(0), n);
  std::array<double, kMaxThreads> partial{};
  int team = 1;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
  {
#ifdef _OPENMP
    const int t = omp_get_thread_num(), size = omp_get_num_threads();
#else
    const int t = 0, size = 1;
#endif
    if (t == 0)
      team = size;
    partial[t] = body(n * t / size, n * (t + 1) / size);
  }
  double sum = 0.0;
  for (int t = 0; t < team; ++t)
    sum += partial[t];
  return sum;
}

/// parallel_chunks with each thread's chunk cut into blocks of at most 1024 values, body(lo, hi)
/// called per block and the results summed: a body that updates a block and then sums it (with
/// Eigen, whose reductions vectorize where a loop's `s += ...` does not) finds the block in L1.
template <typename Body> double parallel_blocks(Eigen::Index n, Body&& body) {
  constexpr Eigen::Index kBlock = 1024;
  return parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
    double sum = 0.0;
    for (Eigen::Index b = lo; b < hi; b += kBlock)
      sum += body(b, std::min(hi, b + kBlock));
    return sum;
  });
}

/// sum_i a_i b_i.
inline double parallel_dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double* pa = a.data();
  const double* pb = b.data();
  return parallel_chunks(a.size(), [&](Eigen::Index lo, Eigen::Index hi) {
    return Eigen::Map<const Eigen::VectorXd>(pa + lo, hi - lo)
        .dot(Eigen::Map<const Eigen::VectorXd>(pb + lo, hi - lo));
  });
}

} // namespace dpgen
