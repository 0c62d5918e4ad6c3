// Issue 23's measurements, each at 1 and 2 threads (the last argument), neighbours in one run so
// that their ratios are taken side by side (scripts/bench_speed.sh builds this with plain -O3
// and with -O3 -march=native and writes the tables):
//  - the unrolled upwind loop (full tape) from 256 to 4M cells: forward alone, gradient with a
//    reused CheckpointWorkspace (sized by one untimed call: a training loop's later calls),
//    gradient allocating its tape per call (what every call did before the workspace); how much
//    the heap grew during a call when its tape is complete;
//  - MG-PCG (setup + solve of -div(k grad p) = b, periodic, tol 1e-8) from 256² to 2048²;
//  - the flow solver: T steps forward against the gradient through them.
#include "dpgen/checkpoint.hpp"
#include "dpgen/implicit_solve.hpp"
#include "dpgen/solvers/flow2d.hpp"
#include "dpgen/solvers/multigrid.hpp"
#include "kernels.hpp"
#include "neg_div_k_grad_periodic2d_adjoint.hpp"
#include "operators.hpp"
#include "upwind_step_adjoint.hpp"

#include <benchmark/benchmark.h>
#include <malloc.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

namespace {

using Eigen::VectorXd;

size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

// Steps of the unrolled loop at n cells: 2^24 cell-steps, at least 16 and at most 10^4 steps
// (README's unrolled-loop table: 10^4 steps on 256 cells).
int upwind_steps(int n) { return std::clamp((1 << 24) / n, 16, 10000); }

// Argument 0: cells; 1: 0 = forward, 1 = gradient with a reused workspace, 2 = gradient with a
// tape allocated and zero-filled per call; 2: threads.
void BM_unrolled_upwind(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), mode = static_cast<int>(state.range(1));
  omp_set_num_threads(static_cast<int>(state.range(2)));
  const int steps = upwind_steps(n);
  const double dx = 1.0 / n, dt = 0.5 * dx;
  VectorXd d0(n), u(n), u_adj(n);
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) / n;
    d0[i] = std::exp(-std::pow((x - 0.5) / 0.1, 2));
    u[i] = 0.3 + 0.2 * std::sin(6.28318 * x);
  }
  auto step = [&](int, const VectorXd& d, VectorXd& next) {
    upwind_step(d.data(), u.data(), next.data(), n, dt, dx);
  };
  auto step_adjoint = [&](int, const VectorXd& d, const VectorXd& next_adj, VectorXd& d_adj) {
    upwind_step_adjoint(d.data(), d_adj.data(), u.data(), u_adj.data(), next_adj.data(), n, dt, dx);
  };
  size_t base = 0, growth = 0; // heap in use before a call; above that when the tape is full
  auto loss = [&](int t, const VectorXd& d, VectorXd& d_adj) {
    if (t != steps)
      return 0.0;
    const size_t now = heap_in_use(); // once per call: the first loss term, tape complete
    growth = now > base ? now - base : 0;
    d_adj += 2.0 * d;
    return d.squaredNorm();
  };
  dpgen::CheckpointOptions options; // full tape
#ifndef DPGEN_BENCH_BASELINE
  dpgen::CheckpointWorkspace workspace;
#endif
  dpgen::UnrolledGradient result;
  VectorXd a = d0, b(n);
#ifndef DPGEN_BENCH_BASELINE
  if (mode == 1) { // the first call sizes the workspace; the timed ones are a training loop's
    options.step_assigns_every_element = true;
    dpgen::unrolled_gradient(d0, steps, step, step_adjoint, loss, options, &workspace, result);
  }
#endif
  for (auto _ : state) {
    if (mode == 0) {
      a = d0;
      for (int t = 0; t < steps; ++t) {
        step(t, a, b);
        a.swap(b);
      }
      benchmark::DoNotOptimize(a.data());
    } else {
      u_adj.setZero();
      base = heap_in_use();
      if (mode == 1) {
#ifdef DPGEN_BENCH_BASELINE // the runtime before the workspace: as mode 2
        result = dpgen::unrolled_gradient(d0, steps, step, step_adjoint, loss, options);
#else
        options.step_assigns_every_element = true; // upwind_step writes every cell
        dpgen::unrolled_gradient(d0, steps, step, step_adjoint, loss, options, &workspace, result);
#endif
      } else {
#ifndef DPGEN_BENCH_BASELINE
        options.step_assigns_every_element = false;
#endif
        result = dpgen::unrolled_gradient(d0, steps, step, step_adjoint, loss, options);
      }
      benchmark::DoNotOptimize(result.state_adjoint.data());
    }
  }
  state.counters["steps"] = steps;
  state.counters["heap_growth_bytes"] = static_cast<double>(growth);
}

struct Poisson {
  int nx;
  double h;
  VectorXd k, b;
  explicit Poisson(int n) : nx(n), h(1.0 / n), k(n * n), b(n * n) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) * h, y = (j + 0.5) * h;
        k[j * n + i] = 1.0 + 0.5 * std::sin(6.28318 * x) * std::cos(6.28318 * y);
        b[j * n + i] = std::sin(6.28318 * x) + std::cos(12.5664 * y);
      }
  }
};

// Setup + MG-PCG solve, a coefficient seen for the first time (as bench_solvers' forward), the
// operator as the user wrote it (`op`: the kernel) or its generated parallel forward.
void mgpcg(benchmark::State& state, const dpgen::LevelOperator& op) {
  const int n = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  Poisson pr(n);
  const auto periodic = dpgen::Boundaries::all(dpgen::Boundary::periodic);
  dpgen::CgWorkspace workspace;
  int iterations = 0;
  for (auto _ : state) {
    dpgen::Multigrid mg(n, n, pr.h, periodic, op, pr.k);
    dpgen::CgOptions options;
    options.relative_tolerance = 1e-8;
    options.remove_null_space_mean = true;
    options.preconditioner = mg.preconditioner();
    options.workspace = &workspace;
    auto r = dpgen::solve_forward(mg.fine_operator(), pr.b, options);
    iterations = r.summary.iterations;
    benchmark::DoNotOptimize(r.solution.data());
  }
  state.counters["cg_iterations"] = iterations;
  state.counters["ns_per_cell"] =
      benchmark::Counter(static_cast<double>(n) * n, benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

void BM_mgpcg(benchmark::State& state) { mgpcg(state, neg_div_k_grad_periodic2d); }
// The same bits (its interior loop split from the periodic wrap and vectorized).
void BM_mgpcg_parallel_forward(benchmark::State& state) {
  mgpcg(state, neg_div_k_grad_periodic2d_parallel_forward);
}

// T = 4 flow steps (closed box, semi-Lagrangian, a plume's inflow) at n x n: argument 1:
// 0 = forward, 1 = gradient w.r.t. the initial state and the inflow (full tape, reused
// workspace).
void BM_flow(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), mode = static_cast<int>(state.range(1));
  omp_set_num_threads(static_cast<int>(state.range(2)));
  constexpr int steps = 4;
  VectorXd inflow = VectorXd::Zero(n * n);
  for (int j = 0; j < n / 8; ++j)
    for (int i = 3 * n / 8; i < 5 * n / 8; ++i)
      inflow[j * n + i] = 0.2;
  dpgen::FlowOptions fo;
  fo.dt = 0.5;
  dpgen::Flow2d flow(n, n, 1.0, inflow, fo);
  const VectorXd s0 = VectorXd::Zero(flow.state_size());
  VectorXd inflow_adj = VectorXd::Zero(n * n);
  auto step = [&](int, const VectorXd& s, VectorXd& next) { flow.step(s, next); };
  auto step_adjoint = [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
    flow.step_adjoint(s, next_adj, s_adj, inflow_adj);
  };
  auto loss = [&](int t, const VectorXd& s, VectorXd& s_adj) {
    if (t != steps)
      return 0.0;
    s_adj += s;
    return 0.5 * s.squaredNorm();
  };
#ifndef DPGEN_BENCH_BASELINE
  dpgen::CheckpointWorkspace workspace;
#endif
  dpgen::UnrolledGradient result;
  VectorXd a(flow.state_size()), b(flow.state_size());
#ifndef DPGEN_BENCH_BASELINE
  if (mode == 1) // sizes the workspace
    dpgen::unrolled_gradient(s0, steps, step, step_adjoint, loss, {}, &workspace, result);
#endif
  for (auto _ : state) {
    if (mode == 0) {
      a = s0;
      for (int t = 0; t < steps; ++t) {
        step(t, a, b);
        a.swap(b);
      }
      benchmark::DoNotOptimize(a.data());
    } else {
      inflow_adj.setZero();
#ifdef DPGEN_BENCH_BASELINE
      result = dpgen::unrolled_gradient(s0, steps, step, step_adjoint, loss);
#else
      dpgen::unrolled_gradient(s0, steps, step, step_adjoint, loss, {}, &workspace, result);
#endif
      benchmark::DoNotOptimize(result.state_adjoint.data());
    }
  }
  state.counters["pressure_iterations"] = flow.forward_pressure_summary().iterations;
}

} // namespace

BENCHMARK(BM_unrolled_upwind)
    ->ArgsProduct({{256, 4096, 65536, 1 << 20, 1 << 22}, {0, 1, 2}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_mgpcg)->ArgsProduct({{256, 512, 1024, 2048}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_mgpcg_parallel_forward)
    ->ArgsProduct({{256, 512, 1024, 2048}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_flow)->ArgsProduct({{128, 256}, {0, 1}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
