// Both cores for code that was written serial: a 2D row-major stencil kernel run on horizontal
// strips of its grid in parallel (for_row_strips, run_by_row_strips), and the vector loops of the
// solvers (fused updates, reductions in a fixed order) with OpenMP. Without OpenMP, or on one
// thread, everything runs serially; results depend on the number of threads only through the order
// of the sums in reductions, never from run to run.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <utility>
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

// Below this many values a vector loop stays on one thread. Measured on the 2-core VMs this was
// tuned on (an axpy and a dot, in cache, 1 against 2 threads, medians of 4000 alternating
// calls): 2 threads lose below 4K values (0.5-0.8x at 2K), break even at 8K (1.1-1.3x) and gain
// from 16K (1.5-1.9x: a pass over 16K doubles takes about 10 us, a parallel region 1-2).
constexpr Eigen::Index kParallelValues = 16384;

// Below this many values a stencil kernel is not split into row strips (for_row_strips): a
// strip computes and drops two halo rows and the periodic end strips copy their inputs, which
// costs more than it gives on a grid that fits in the caches anyway.
constexpr Eigen::Index kParallelStripValues = 65536;

// One strip's buffers per thread, shared by every kernel and store (kept by the thread:
// OpenMP's threads live on, so a call allocates nothing once the sizes have been seen).
struct StripBuffers {
  std::vector<double> copies; // a periodic end strip's input rows
  std::vector<double> result; // the strip's output rows
  int depth = 0;              // > 0 while this thread runs a strip
};
inline StripBuffers& strip_buffers() {
  thread_local StripBuffers buffers;
  return buffers;
}

} // namespace detail

/// The shape of a kernel for for_row_strips and run_by_row_strips: `rows` input rows of `in_width`
/// values (every input array), `out_per_in * rows` output rows of `out_width` values; output rows
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
/// strips of the grid, on every thread, and hands each strip's output rows to
/// `store(first, count, values)`: the values [first, first + count) of the output the kernel
/// gives on the whole grid (kernel(inputs, out, shape.rows); row-major, out_per_in * out_width
/// values per input row), in a buffer of the thread's. This holds for any kernel of the shape
/// described above. A strip gets one extra input row on each side (its neighbours' rows, or
/// the wrapped row on a periodic grid); the kernel treats them as boundary rows and their
/// output is not stored. Each strip's output is written to a buffer that stays in the core's
/// cache (about kStripValues values) and stored from there: a store that combines it with
/// other fields (a Jacobi update, a residual) reads it from the cache, not from memory. Only
/// the periodic end strips copy their inputs (their wrapped row is not adjacent). Strips are
/// at least 8 rows high, and two or more per thread where the grid has the rows; a thread
/// runs neighbouring strips, so their shared halo rows are read from its cache. `force_strips`:
/// split even where one call would do (one thread, a small grid), to check that a kernel has the
/// shape, bit for bit. Returns false (and does nothing) when the grid is too small to split, or
/// when called from a kernel or store of another strip run on the same thread: call the kernel
/// once.
template <std::size_t N, typename Kernel, typename Store>
bool for_row_strips(const RowStripShape& shape, const std::array<const double*, N>& inputs,
                    Kernel&& kernel, Store&& store, bool force_strips = false) {
  // Output values per strip (512 KiB): the strip's output stays in L2 until it is stored. The
  // budget gives at least 16 rows (so the two halo rows, computed and dropped, add at most 1/8;
  // 1/16 up to 2048 output values per row); a grid with fewer than 32 rows per thread gets
  // strips of at least 8.
  constexpr Eigen::Index kStripValues = 65536;
  // Inside a kernel or store of another for_row_strips call on this thread: its strip is in
  // this thread's buffers, so this one runs whole (the caller calls the kernel once).
  if (detail::strip_buffers().depth > 0)
    return false;
  const int threads = detail::max_threads();
  const int rows = shape.rows;
  const Eigen::Index in_w = shape.in_width;
  const Eigen::Index out_row = shape.out_per_in * shape.out_width; // output values per input row
  const Eigen::Index values = Eigen::Index(rows) * std::max(in_w, out_row);
  if (rows < 16 || (!force_strips && (threads < 2 || values < detail::kParallelStripValues)))
    return false;
  const Eigen::Index by_cache =
      std::max<Eigen::Index>(16, kStripValues / std::max<Eigen::Index>(out_row, 1));
  const int height = static_cast<int>(
      std::max<Eigen::Index>(8, std::min<Eigen::Index>(by_cache, rows / (2 * threads))));
  const int strips = std::max(2, rows / height); // each at least `height` rows
  const auto strip_begin = [&](int s) { return static_cast<int>(Eigen::Index(rows) * s / strips); };

  const auto run_strip = [&](int s, detail::StripBuffers& buffers) {
    std::vector<double>& copies = buffers.copies;
    std::vector<double>& result = buffers.result;
    const int a = strip_begin(s), b = strip_begin(s + 1);
    const int below = a > 0 || shape.periodic ? 1 : 0, above = b < rows || shape.periodic ? 1 : 0;
    const int n = b - a + below + above; // input rows the kernel sees
    std::array<const double*, N> in;
    if (shape.periodic && (a == 0 || b == rows)) { // a wrapped halo row: copy the strip's rows
      copies.resize(static_cast<std::size_t>(N * n * in_w));
      const int first = a > 0 ? a - 1 : rows - 1, last = b < rows ? b : 0;
      for (std::size_t i = 0; i < N; ++i) {
        double* copy = copies.data() + i * n * in_w;
        std::memcpy(copy, inputs[i] + first * in_w, sizeof(double) * in_w);
        std::memcpy(copy + in_w, inputs[i] + a * in_w, sizeof(double) * (b - a) * in_w);
        std::memcpy(copy + (n - 1) * in_w, inputs[i] + last * in_w, sizeof(double) * in_w);
        in[i] = copy;
      }
    } else { // the strip's rows and its halo lie in place
      for (std::size_t i = 0; i < N; ++i)
        in[i] = inputs[i] + (a - below) * in_w;
    }
    result.resize(static_cast<std::size_t>(n * out_row));
    kernel(in, result.data(), n);
    store(a * out_row, (b - a) * out_row, result.data() + below * out_row);
  };
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
  {
    detail::StripBuffers& buffers = detail::strip_buffers();
    ++buffers.depth;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
    for (int s = 0; s < strips; ++s)
      run_strip(s, buffers);
    --buffers.depth;
  }
  return true;
}

/// for_row_strips storing every strip's output rows into `out`, which then holds what
/// kernel(inputs, out, shape.rows) writes on the whole grid (`out` must not overlap an input).
template <std::size_t N, typename Kernel>
bool run_by_row_strips(const RowStripShape& shape, const std::array<const double*, N>& inputs,
                       double* out, Kernel&& kernel, bool force_strips = false) {
  return for_row_strips<N>(
      shape, inputs, std::forward<Kernel>(kernel),
      [out](Eigen::Index first, Eigen::Index count, const double* values) {
        std::memcpy(out + first, values, sizeof(double) * count);
      },
      force_strips);
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
