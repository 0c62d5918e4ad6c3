// Solvers and time loops: Jacobi-preconditioned and multigrid-preconditioned CG,
// forward solve against its implicit backward pass (one more solve plus the
// generated operator adjoint), heap memory of the implicit rule against
// differentiating through the unrolled CG iterations, and an unrolled upwind
// time loop with a full tape against Revolve. The solver benchmarks run on one
// thread (the generated kernels would otherwise use OpenMP, the rest not).
#include "dpgen/checkpoint.hpp"
#include "dpgen/implicit_solve.hpp"
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
#include <vector>

namespace {

using Eigen::VectorXd;

// Bytes the heap holds right now (small blocks + mmap'ed large ones).
size_t heap_in_use() {
  struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

struct Poisson {
  int nx;
  double h;
  VectorXd k, b;
  explicit Poisson(int n) : nx(n), h(1.0 / n), k(n * n), b(n * n) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double x = (i + 0.5) * h, y = (j + 0.5) * h;
        k[j * n + i] = 1.0 + 0.5 * std::sin(6.28318 * x) * std::cos(6.28318 * y);
        b[j * n + i] = std::sin(6.28318 * x) + std::cos(12.5664 * y);
      }
  }
  void apply(const VectorXd& p, VectorXd& y) const {
    neg_div_k_grad_periodic2d(p.data(), k.data(), y.data(), nx, nx, h);
  }
  dpgen::CgOptions options() const {
    dpgen::CgOptions o;
    o.relative_tolerance = 1e-8;
    o.max_iterations = 100000;
    o.remove_null_space_mean = true;
    return o;
  }
  const dpgen::Boundaries periodic = dpgen::Boundaries::all(dpgen::Boundary::periodic);
  // Jacobi-preconditioned CG: M = diag(A), found once (not timed) by probing the operator.
  dpgen::CgOptions jacobi_options() const {
    dpgen::CgOptions o = options();
    o.jacobi_diagonal = dpgen::operator_diagonal(neg_div_k_grad_periodic2d, k, nx, nx, h, periodic);
    return o;
  }
  // theta_bar -= (d(A(k) x)/dk)^T lambda: the generated adjoint w.r.t. k.
  void adjoint_k(const VectorXd& xs, const VectorXd& lambda, VectorXd& g) const {
    VectorXd p_adj = VectorXd::Zero(xs.size());
    neg_div_k_grad_periodic2d_adjoint(xs.data(), p_adj.data(), k.data(), g.data(), lambda.data(),
                                      nx, nx, h);
  }
};

// Jacobi-preconditioned CG, the yardstick of the multigrid-preconditioned one.
void BM_cg_forward(benchmark::State& state) {
  omp_set_num_threads(1);
  Poisson pr(static_cast<int>(state.range(0)));
  const dpgen::CgOptions options = pr.jacobi_options();
  int iterations = 0;
  for (auto _ : state) {
    auto r = dpgen::solve_forward([&](const VectorXd& x, VectorXd& y) { pr.apply(x, y); }, pr.b,
                                  options);
    iterations = r.summary.iterations;
    benchmark::DoNotOptimize(r.solution.data());
  }
  state.counters["cg_iterations"] = iterations;
}

void BM_cg_backward_implicit(benchmark::State& state) {
  omp_set_num_threads(1);
  Poisson pr(static_cast<int>(state.range(0)));
  const dpgen::CgOptions options = pr.jacobi_options();
  auto apply = [&](const VectorXd& x, VectorXd& y) { pr.apply(x, y); };
  const VectorXd x = dpgen::solve_forward(apply, pr.b, options).solution;
  // A loss gradient as smooth as the forward right-hand side, so both solves
  // face the same conditioning: the difference is the implicit rule's own cost.
  const VectorXd x_bar = pr.b;
  auto op_adjoint = [&](const VectorXd& xs, const VectorXd& l, VectorXd& g) {
    pr.adjoint_k(xs, l, g);
  };
  int iterations = 0;
  for (auto _ : state) {
    VectorXd b_bar, k_bar = VectorXd::Zero(pr.k.size());
    auto r = dpgen::implicit_solve_backward(apply, op_adjoint, x, x_bar, b_bar, k_bar, options);
    iterations = r.summary.iterations;
    benchmark::DoNotOptimize(k_bar.data());
  }
  state.counters["cg_iterations"] = iterations;
}

// One application of the operator kernel: the unit in which the solves' costs are
// compared across sizes (its time per cell grows once the fields leave the caches).
void BM_operator(benchmark::State& state) {
  Poisson pr(static_cast<int>(state.range(0)));
  VectorXd y(pr.b.size());
  for (auto _ : state) {
    pr.apply(pr.b, y);
    benchmark::DoNotOptimize(y.data());
  }
}

// The multigrid setup alone: coefficients averaged level by level, diagonals probed
// (9 operator applications per level), the coarsest grid factored.
void BM_mg_setup(benchmark::State& state) {
  omp_set_num_threads(1);
  Poisson pr(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    dpgen::Multigrid mg(pr.nx, pr.nx, pr.h, pr.periodic, neg_div_k_grad_periodic2d, pr.k);
    benchmark::DoNotOptimize(&mg);
  }
}

// A forward solve with a coefficient seen for the first time: multigrid setup plus
// MG-preconditioned CG.
void BM_mgpcg_forward(benchmark::State& state) {
  omp_set_num_threads(1);
  Poisson pr(static_cast<int>(state.range(0)));
  int iterations = 0, levels = 0;
  for (auto _ : state) {
    dpgen::Multigrid mg(pr.nx, pr.nx, pr.h, pr.periodic, neg_div_k_grad_periodic2d, pr.k);
    dpgen::CgOptions options = pr.options();
    options.preconditioner = mg.preconditioner();
    auto r = dpgen::solve_forward(mg.fine_operator(), pr.b, options);
    iterations = r.summary.iterations;
    levels = mg.levels();
    benchmark::DoNotOptimize(r.solution.data());
  }
  state.counters["cg_iterations"] = iterations;
  state.counters["mg_levels"] = levels;
}

// The implicit backward pass of that solve: A^T lambda = x_bar preconditioned by the
// forward pass's multigrid (A^T = A, no second setup), then the generated adjoint w.r.t. k.
void BM_mgpcg_backward_implicit(benchmark::State& state) {
  omp_set_num_threads(1);
  Poisson pr(static_cast<int>(state.range(0)));
  dpgen::Multigrid mg(pr.nx, pr.nx, pr.h, pr.periodic, neg_div_k_grad_periodic2d, pr.k);
  dpgen::CgOptions options = pr.options();
  options.preconditioner = mg.preconditioner();
  const VectorXd x = dpgen::solve_forward(mg.fine_operator(), pr.b, options).solution;
  const VectorXd x_bar = pr.b;
  auto op_adjoint = [&](const VectorXd& xs, const VectorXd& l, VectorXd& g) {
    pr.adjoint_k(xs, l, g);
  };
  int iterations = 0;
  for (auto _ : state) {
    VectorXd b_bar, k_bar = VectorXd::Zero(pr.k.size());
    auto r = dpgen::implicit_solve_backward(mg.fine_operator(), op_adjoint, x, x_bar, b_bar, k_bar,
                                            options);
    iterations = r.summary.iterations;
    benchmark::DoNotOptimize(k_bar.data());
  }
  state.counters["cg_iterations"] = iterations;
}

// Heap growth during a gradient of a Poisson solve with `iters` CG iterations
// (fixed, no tolerance): the implicit rule (backward = one more solve) against
// recording every iteration's vectors to differentiate through them.
void BM_cg_gradient_memory(benchmark::State& state) {
  const bool unrolled = state.range(0) != 0;
  const int iters = static_cast<int>(state.range(1));
  Poisson pr(128);
  const long n = pr.b.size();
  auto apply = [&](const VectorXd& x, VectorXd& y) { pr.apply(x, y); };
  size_t peak = 0;
  for (auto _ : state) {
    const size_t base = heap_in_use();
    peak = 0;
    auto sample = [&] { peak = std::max(peak, heap_in_use() - base); };
    dpgen::CgOptions o = pr.options();
    o.relative_tolerance = 0, o.max_iterations = iters, o.throw_on_failure = false;
    if (!unrolled) {
      auto sampled = [&](const VectorXd& x, VectorXd& y) { apply(x, y), sample(); };
      VectorXd x = dpgen::solve_forward(sampled, pr.b, o).solution;
      VectorXd lambda = dpgen::solve_backward(sampled, x, o).solution;
      benchmark::DoNotOptimize(lambda.data());
    } else {
      // CG as a tape: every iterate's direction, residual and A p kept for
      // the reverse sweep (what backpropagating through the iterations needs).
      std::vector<VectorXd> tape;
      VectorXd x = VectorXd::Zero(n), r = pr.b.array() - pr.b.mean(), p = r, q(n);
      double rr = r.squaredNorm();
      for (int it = 0; it < iters; ++it) {
        apply(p, q);
        double alpha = rr / p.dot(q);
        tape.push_back(p), tape.push_back(r), tape.push_back(q);
        x += alpha * p, r -= alpha * q;
        double rr_new = r.squaredNorm();
        p = r + (rr_new / rr) * p, rr = rr_new;
        sample();
      }
      benchmark::DoNotOptimize(x.data());
    }
  }
  state.counters["peak_heap_bytes"] = static_cast<double>(peak);
  state.counters["field_bytes"] = static_cast<double>(n * sizeof(double));
}

// T upwind steps on 256 cells; the loss is |d_T|^2; the gradient w.r.t. d0
// and u (accumulated over every step).
constexpr int kCells = 256;
constexpr int kSteps = 10000;

struct TimeLoop {
  VectorXd d0 = VectorXd(kCells), u = VectorXd(kCells);
  TimeLoop() {
    for (int i = 0; i < kCells; ++i) {
      double x = (i + 0.5) / kCells;
      d0[i] = std::exp(-std::pow((x - 0.5) / 0.1, 2));
      u[i] = 0.3 + 0.2 * std::sin(6.28318 * x);
    }
  }
};

void BM_timeloop_forward(benchmark::State& state) {
  TimeLoop tl;
  const double dx = 1.0 / kCells, dt = 0.5 * dx;
  for (auto _ : state) {
    VectorXd d = tl.d0, next(kCells);
    for (int t = 0; t < kSteps; ++t) {
      upwind_step(d.data(), tl.u.data(), next.data(), kCells, dt, dx);
      d.swap(next);
    }
    benchmark::DoNotOptimize(d.data());
  }
}

// Argument: 0 = full tape, s > 0 = Revolve with s snapshots.
void BM_timeloop_gradient(benchmark::State& state) {
  TimeLoop tl;
  const double dx = 1.0 / kCells, dt = 0.5 * dx;
  dpgen::CheckpointOptions cp;
  if (state.range(0) > 0) {
    cp.strategy = dpgen::CheckpointStrategy::revolve;
    cp.snapshots = static_cast<int>(state.range(0));
  }
  dpgen::CheckpointStats stats;
  for (auto _ : state) {
    VectorXd u_adj = VectorXd::Zero(kCells);
    auto step = [&](int, const VectorXd& d, VectorXd& next) {
      upwind_step(d.data(), tl.u.data(), next.data(), kCells, dt, dx);
    };
    auto step_adjoint = [&](int, const VectorXd& d, const VectorXd& next_adj, VectorXd& d_adj) {
      upwind_step_adjoint(d.data(), d_adj.data(), tl.u.data(), u_adj.data(), next_adj.data(),
                          kCells, dt, dx);
    };
    auto loss = [&](int t, const VectorXd& d, VectorXd& d_adj) {
      if (t != kSteps)
        return 0.0;
      d_adj += 2.0 * d;
      return d.squaredNorm();
    };
    auto g = dpgen::unrolled_gradient(tl.d0, kSteps, step, step_adjoint, loss, cp);
    stats = g.stats;
    benchmark::DoNotOptimize(u_adj.data());
  }
  state.counters["forward_steps"] = static_cast<double>(stats.forward_steps);
  state.counters["predicted_steps"] =
      state.range(0) > 0
          ? static_cast<double>(dpgen::revolve_forward_steps(kSteps, state.range(0)) + 1)
          : static_cast<double>(kSteps);
  state.counters["peak_state_bytes"] = static_cast<double>(stats.peak_snapshot_bytes);
}

} // namespace

BENCHMARK(BM_cg_forward)->RangeMultiplier(2)->Range(64, 1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_cg_backward_implicit)
    ->Arg(64)
    ->Arg(128)
    ->Arg(256)
    ->Arg(512)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_operator)->RangeMultiplier(2)->Range(64, 1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_mg_setup)->RangeMultiplier(2)->Range(64, 1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_mgpcg_forward)->RangeMultiplier(2)->Range(64, 1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_mgpcg_backward_implicit)
    ->RangeMultiplier(2)
    ->Range(64, 1024)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_cg_gradient_memory)
    ->ArgsProduct({{0, 1}, {25, 100, 400}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timeloop_forward)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_timeloop_gradient)->Arg(0)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
