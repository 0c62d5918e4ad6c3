// Generated adjoints against their forward kernels (as written, and peeled
// where the written one does not vectorize), hand-written gather adjoints and
// scatter adjoints (the form general AD tools emit), side by side in one run.
// Each benchmark's argument is the OpenMP thread count (the forward kernels
// and the scatter adjoints are serial code; they run at both counts too).
#include "hand_written.hpp"

#include "burgers_step_adjoint.hpp"
#include "divergence2d_adjoint.hpp"
#include "kernels.hpp"
#include "laplacian2d_adjoint.hpp"
#include "laplacian3d_adjoint.hpp"
#include "test_kernels.hpp"
#include "upwind_step_adjoint.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <random>
#include <vector>

namespace {

constexpr int kN2 = 2048;    // 2D grids: 2048 x 2048
constexpr int kN1 = 1 << 22; // 1D: 2^22 cells
constexpr int kN3 = 160;     // 3D: 160^3
// In cache (the `_cache` benchmarks of the generated and hand-written adjoints):
// 2^14 cells or fewer, every array of a kernel together within one core's L2.
constexpr int kC2 = 128;     // 128 x 128
constexpr int kC1 = 1 << 14; // 2^14
constexpr int kC3 = 24;      // 24^3

std::vector<double> random_field(size_t n, double lo, double hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  std::vector<double> v(n);
  for (auto& x : v)
    x = dist(rng);
  return v;
}

// Runs `body` as the timed loop with `state.range(0)` OpenMP threads, and
// reports the cells processed per second and, given the bytes a cell must
// move at the least (each array read once, each written once: STREAM's
// count), the bytes per second.
template <typename Body>
void run(benchmark::State& state, size_t cells, Body&& body, int bytes_per_cell = 0) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    body();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(cells));
  if (bytes_per_cell > 0)
    state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                            static_cast<int64_t>(cells) * bytes_per_cell);
}

// ---- STREAM triad, a[i] = b[i] + s c[i], on 2048 x 2048 doubles per array ------
// The memory bandwidth the 2D adjoints are held against: 24 bytes per cell,
// threads as the generated loops use them (a static OpenMP split).
struct Triad {
  size_t n = size_t(kN2) * kN2;
  std::vector<double> a = std::vector<double>(n), b = random_field(n, -1, 1, 11),
                      c = random_field(n, -1, 1, 12);
};
void BM_triad(benchmark::State& s) {
  static Triad d;
  const auto n = static_cast<std::ptrdiff_t>(d.n);
  double* a = d.a.data();
  const double *b = d.b.data(), *c = d.c.data();
  run(
      s, d.n,
      [&] {
#pragma omp parallel for schedule(static)
        for (std::ptrdiff_t i = 0; i < n; ++i)
          a[i] = b[i] + 3.0 * c[i];
      },
      24);
}

// ---- laplacian2d -------------------------------------------------------------
struct Lap2 {
  explicit Lap2(int side) : side(side) {}
  int side;
  size_t n = size_t(side) * side;
  std::vector<double> a = random_field(n, -1, 1, 1), out = std::vector<double>(n),
                      g = random_field(n, -1, 1, 2), a_adj = std::vector<double>(n);
};
template <int Side = kN2> Lap2& lap2() {
  static Lap2 d(Side);
  return d;
}
void BM_laplacian2d_forward(benchmark::State& s) {
  auto& d = lap2();
  run(s, d.n, [&] { laplacian2d(d.a.data(), d.out.data(), kN2, kN2, 0.1); });
}
void BM_laplacian2d_forward_peeled(benchmark::State& s) {
  auto& d = lap2();
  run(s, d.n, [&] { hand::laplacian2d_peeled(d.a.data(), d.out.data(), kN2, kN2, 0.1); });
}
template <int Side> void BM_laplacian2d_generated(benchmark::State& s) {
  auto& d = lap2<Side>();
  // seed read, adjoint read and written: 24 bytes per cell
  run(
      s, d.n, [&] { laplacian2d_adjoint(d.a.data(), d.a_adj.data(), d.g.data(), Side, Side, 0.1); },
      24);
}
template <int Side> void BM_laplacian2d_hand(benchmark::State& s) {
  auto& d = lap2<Side>();
  run(
      s, d.n, [&] { hand::laplacian2d_gather(d.a_adj.data(), d.g.data(), Side, Side, 0.1); }, 24);
}
void BM_laplacian2d_scatter(benchmark::State& s) {
  auto& d = lap2();
  run(s, d.n, [&] { hand::laplacian2d_scatter(d.a_adj.data(), d.g.data(), kN2, kN2, 0.1); });
}

// ---- divergence2d ------------------------------------------------------------
struct Div2 {
  explicit Div2(int side) : side(side) {}
  int side;
  size_t n = size_t(side) * side;
  std::vector<double> u = random_field(n, -1, 1, 3), v = random_field(n, -1, 1, 4),
                      out = std::vector<double>(n), g = random_field(n, -1, 1, 5),
                      u_adj = std::vector<double>(n), v_adj = std::vector<double>(n);
};
template <int Side = kN2> Div2& div2() {
  static Div2 d(Side);
  return d;
}
void BM_divergence2d_forward(benchmark::State& s) {
  auto& d = div2();
  run(s, d.n, [&] { divergence2d(d.u.data(), d.v.data(), d.out.data(), kN2, kN2, 0.1); });
}
void BM_divergence2d_forward_peeled(benchmark::State& s) {
  auto& d = div2();
  run(s, d.n,
      [&] { hand::divergence2d_peeled(d.u.data(), d.v.data(), d.out.data(), kN2, kN2, 0.1); });
}
template <int Side> void BM_divergence2d_generated(benchmark::State& s) {
  auto& d = div2<Side>();
  // seed read, two adjoints read and written: 40 bytes per cell
  run(
      s, d.n,
      [&] {
        divergence2d_adjoint(d.u.data(), d.u_adj.data(), d.v.data(), d.v_adj.data(), d.g.data(),
                             Side, Side, 0.1);
      },
      40);
}
template <int Side> void BM_divergence2d_hand(benchmark::State& s) {
  auto& d = div2<Side>();
  run(
      s, d.n,
      [&] {
        hand::divergence2d_gather(d.u_adj.data(), d.v_adj.data(), d.g.data(), Side, Side, 0.1);
      },
      40);
}
void BM_divergence2d_scatter(benchmark::State& s) {
  auto& d = div2();
  run(s, d.n, [&] {
    hand::divergence2d_scatter(d.u_adj.data(), d.v_adj.data(), d.g.data(), kN2, kN2, 0.1);
  });
}

// ---- upwind_step -------------------------------------------------------------
struct Up1 {
  explicit Up1(int cells) : n(size_t(cells)) {}
  size_t n;
  std::vector<double> d = random_field(n, 0, 1, 6), u = random_field(n, -1, 1, 7),
                      out = std::vector<double>(n), g = random_field(n, -1, 1, 8),
                      d_adj = std::vector<double>(n), u_adj = std::vector<double>(n);
};
template <int Cells = kN1> Up1& up1() {
  static Up1 d(Cells);
  return d;
}
const double kDt = 0.2, kDx = 1.0;
void BM_upwind_forward(benchmark::State& s) {
  auto& d = up1();
  run(s, d.n, [&] { upwind_step(d.d.data(), d.u.data(), d.out.data(), kN1, kDt, kDx); });
}
void BM_upwind_forward_peeled(benchmark::State& s) {
  auto& d = up1();
  run(s, d.n, [&] { hand::upwind_peeled(d.d.data(), d.u.data(), d.out.data(), kN1, kDt, kDx); });
}
template <int Cells> void BM_upwind_generated(benchmark::State& s) {
  auto& d = up1<Cells>();
  run(s, d.n, [&] {
    upwind_step_adjoint(d.d.data(), d.d_adj.data(), d.u.data(), d.u_adj.data(), d.g.data(), Cells,
                        kDt, kDx);
  });
}
template <int Cells> void BM_upwind_hand(benchmark::State& s) {
  auto& d = up1<Cells>();
  run(s, d.n, [&] {
    hand::upwind_gather(d.d.data(), d.d_adj.data(), d.u.data(), d.u_adj.data(), d.g.data(), Cells,
                        kDt, kDx);
  });
}
void BM_upwind_scatter(benchmark::State& s) {
  auto& d = up1();
  run(s, d.n, [&] {
    hand::upwind_scatter(d.d.data(), d.d_adj.data(), d.u.data(), d.u_adj.data(), d.g.data(), kN1,
                         kDt, kDx);
  });
}

// ---- laplacian3d (tests/kernels) -----------------------------------------------
struct Lap3 {
  explicit Lap3(int side) : n(size_t(side) * side * side) {}
  size_t n;
  std::vector<double> a = random_field(n, -1, 1, 9), out = std::vector<double>(n),
                      g = random_field(n, -1, 1, 10), a_adj = std::vector<double>(n);
};
template <int Side = kN3> Lap3& lap3() {
  static Lap3 d(Side);
  return d;
}
void BM_laplacian3d_forward(benchmark::State& s) {
  auto& d = lap3();
  run(s, d.n, [&] { laplacian3d(d.a.data(), d.out.data(), kN3, kN3, kN3, 0.1); });
}
template <int Side> void BM_laplacian3d_generated(benchmark::State& s) {
  auto& d = lap3<Side>();
  run(s, d.n,
      [&] { laplacian3d_adjoint(d.a.data(), d.a_adj.data(), d.g.data(), Side, Side, Side, 0.1); });
}
template <int Side> void BM_laplacian3d_hand(benchmark::State& s) {
  auto& d = lap3<Side>();
  run(s, d.n, [&] { hand::laplacian3d_gather(d.a_adj.data(), d.g.data(), Side, Side, Side, 0.1); });
}
void BM_laplacian3d_scatter(benchmark::State& s) {
  auto& d = lap3();
  run(s, d.n, [&] { hand::laplacian3d_scatter(d.a_adj.data(), d.g.data(), kN3, kN3, kN3, 0.1); });
}

// ---- burgers_step (tests/kernels): nonlinear -----------------------------------
struct Burg {
  explicit Burg(int cells) : n(size_t(cells)) {}
  size_t n;
  std::vector<double> u = random_field(n, -1, 1, 11), out = std::vector<double>(n),
                      g = random_field(n, -1, 1, 12), u_adj = std::vector<double>(n);
};
template <int Cells = kN1> Burg& burg() {
  static Burg d(Cells);
  return d;
}
void BM_burgers_forward(benchmark::State& s) {
  auto& d = burg();
  run(s, d.n, [&] { burgers_step(d.u.data(), d.out.data(), kN1, 0.01, 0.1, 0.05); });
}
void BM_burgers_forward_peeled(benchmark::State& s) {
  auto& d = burg();
  run(s, d.n, [&] { hand::burgers_peeled(d.u.data(), d.out.data(), kN1, 0.01, 0.1, 0.05); });
}
template <int Cells> void BM_burgers_generated(benchmark::State& s) {
  auto& d = burg<Cells>();
  run(s, d.n, [&] {
    burgers_step_adjoint(d.u.data(), d.u_adj.data(), d.g.data(), Cells, 0.01, 0.1, 0.05);
  });
}
template <int Cells> void BM_burgers_hand(benchmark::State& s) {
  auto& d = burg<Cells>();
  run(s, d.n, [&] {
    hand::burgers_gather(d.u.data(), d.u_adj.data(), d.g.data(), Cells, 0.01, 0.1, 0.05);
  });
}
void BM_burgers_scatter(benchmark::State& s) {
  auto& d = burg();
  run(s, d.n,
      [&] { hand::burgers_scatter(d.u.data(), d.u_adj.data(), d.g.data(), kN1, 0.01, 0.1, 0.05); });
}

} // namespace

#define THREADS ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()
BENCHMARK(BM_triad) THREADS;
BENCHMARK(BM_laplacian2d_forward) THREADS;
BENCHMARK(BM_laplacian2d_forward_peeled) THREADS;
BENCHMARK_TEMPLATE(BM_laplacian2d_generated, kN2)->Name("BM_laplacian2d_generated") THREADS;
BENCHMARK_TEMPLATE(BM_laplacian2d_generated, kC2)->Name("BM_laplacian2d_generated_cache") THREADS;
BENCHMARK_TEMPLATE(BM_laplacian2d_hand, kN2)->Name("BM_laplacian2d_hand") THREADS;
BENCHMARK_TEMPLATE(BM_laplacian2d_hand, kC2)->Name("BM_laplacian2d_hand_cache") THREADS;
BENCHMARK(BM_laplacian2d_scatter) THREADS;
BENCHMARK(BM_divergence2d_forward) THREADS;
BENCHMARK(BM_divergence2d_forward_peeled) THREADS;
BENCHMARK_TEMPLATE(BM_divergence2d_generated, kN2)->Name("BM_divergence2d_generated") THREADS;
BENCHMARK_TEMPLATE(BM_divergence2d_generated, kC2)->Name("BM_divergence2d_generated_cache") THREADS;
BENCHMARK_TEMPLATE(BM_divergence2d_hand, kN2)->Name("BM_divergence2d_hand") THREADS;
BENCHMARK_TEMPLATE(BM_divergence2d_hand, kC2)->Name("BM_divergence2d_hand_cache") THREADS;
BENCHMARK(BM_divergence2d_scatter) THREADS;
BENCHMARK(BM_upwind_forward) THREADS;
BENCHMARK(BM_upwind_forward_peeled) THREADS;
BENCHMARK_TEMPLATE(BM_upwind_generated, kN1)->Name("BM_upwind_generated") THREADS;
BENCHMARK_TEMPLATE(BM_upwind_generated, kC1)->Name("BM_upwind_generated_cache") THREADS;
BENCHMARK_TEMPLATE(BM_upwind_hand, kN1)->Name("BM_upwind_hand") THREADS;
BENCHMARK_TEMPLATE(BM_upwind_hand, kC1)->Name("BM_upwind_hand_cache") THREADS;
BENCHMARK(BM_upwind_scatter) THREADS;
BENCHMARK(BM_laplacian3d_forward) THREADS;
BENCHMARK_TEMPLATE(BM_laplacian3d_generated, kN3)->Name("BM_laplacian3d_generated") THREADS;
BENCHMARK_TEMPLATE(BM_laplacian3d_generated, kC3)->Name("BM_laplacian3d_generated_cache") THREADS;
BENCHMARK_TEMPLATE(BM_laplacian3d_hand, kN3)->Name("BM_laplacian3d_hand") THREADS;
BENCHMARK_TEMPLATE(BM_laplacian3d_hand, kC3)->Name("BM_laplacian3d_hand_cache") THREADS;
BENCHMARK(BM_laplacian3d_scatter) THREADS;
BENCHMARK(BM_burgers_forward) THREADS;
BENCHMARK(BM_burgers_forward_peeled) THREADS;
BENCHMARK_TEMPLATE(BM_burgers_generated, kN1)->Name("BM_burgers_generated") THREADS;
BENCHMARK_TEMPLATE(BM_burgers_generated, kC1)->Name("BM_burgers_generated_cache") THREADS;
BENCHMARK_TEMPLATE(BM_burgers_hand, kN1)->Name("BM_burgers_hand") THREADS;
BENCHMARK_TEMPLATE(BM_burgers_hand, kC1)->Name("BM_burgers_hand_cache") THREADS;
BENCHMARK(BM_burgers_scatter) THREADS;
BENCHMARK_MAIN();
