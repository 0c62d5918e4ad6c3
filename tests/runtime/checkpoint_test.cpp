// Tests of dpgen/checkpoint.hpp on a nonlinear (viscous Burgers) step: full tape and Revolve
// agree bit for bit, the gradient matches finite differences, Revolve's step count is
// Griewank's minimum and its memory follows the snapshot count; errors.
#include "dpgen/checkpoint.hpp"

#include <doctest/doctest.h>
#include <malloc.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;

// Periodic viscous Burgers, forward Euler, central differences:
//   u'[i] = u[i] - dt u[i] (u[i+1] - u[i-1]) / (2 dx) + nu dt (u[i+1] - 2 u[i] + u[i-1]) / dx^2
//           + dt f[i]
// with parameters nu (viscosity) and f (forcing) used by every step.
struct Burgers {
  int n = 48;
  double dx = 1.0 / 48, dt = 0.004, nu = 0.02;
  VectorXd forcing;
  // Parameter adjoints, accumulated over all steps by step_adjoint.
  double nu_adj = 0.0;
  VectorXd forcing_adj;

  Burgers() {
    forcing.resize(n);
    for (int i = 0; i < n; ++i)
      forcing[i] = 0.3 * std::cos(2.0 * M_PI * i * dx);
    forcing_adj = VectorXd::Zero(n);
  }

  VectorXd initial_state() const {
    VectorXd u(n);
    for (int i = 0; i < n; ++i)
      u[i] = 0.5 * std::sin(2.0 * M_PI * i * dx) + 0.1;
    return u;
  }

  void step(const VectorXd& u, VectorXd& out) const {
    const double c = dt / (2.0 * dx), d = nu * dt / (dx * dx);
    for (int i = 0; i < n; ++i) {
      const int ip = (i + 1) % n, im = (i + n - 1) % n;
      out[i] =
          u[i] - c * u[i] * (u[ip] - u[im]) + d * (u[ip] - 2.0 * u[i] + u[im]) + dt * forcing[i];
    }
  }

  // Hand-written adjoint: u_adj += (du'/du)^T g, nu_adj += (du'/dnu)^T g, f_adj += dt g.
  void step_adjoint(const VectorXd& u, const VectorXd& g, VectorXd& u_adj) {
    const double c = dt / (2.0 * dx), d = nu * dt / (dx * dx);
    for (int i = 0; i < n; ++i) {
      const int ip = (i + 1) % n, im = (i + n - 1) % n;
      u_adj[i] += g[i] * (1.0 - c * (u[ip] - u[im]) - 2.0 * d);
      u_adj[ip] += g[i] * (-c * u[i] + d);
      u_adj[im] += g[i] * (c * u[i] + d);
      nu_adj += g[i] * dt * (u[ip] - 2.0 * u[i] + u[im]) / (dx * dx);
      forcing_adj[i] += g[i] * dt;
    }
  }
};

// Which states the loss looks at.
enum class LossKind { final_only, several_times, trajectory };

// l_t(s) = 1/2 |s - target_t|^2 at the selected times (target_t a travelling wave).
struct Loss {
  LossKind kind;
  int steps;

  bool active(int t) const {
    switch (kind) {
    case LossKind::final_only:
      return t == steps;
    case LossKind::several_times:
      return t == steps / 4 || t == steps / 2 || t == steps;
    case LossKind::trajectory:
      return true;
    }
    return false;
  }
  VectorXd target(int t, int n) const {
    VectorXd y(n);
    for (int i = 0; i < n; ++i)
      y[i] = 0.4 * std::sin(2.0 * M_PI * (i / double(n) - 0.01 * t));
    return y;
  }
  double operator()(int t, const VectorXd& s, VectorXd& s_adj) const {
    if (!active(t))
      return 0.0;
    const VectorXd diff = s - target(t, static_cast<int>(s.size()));
    s_adj += diff;
    return 0.5 * diff.squaredNorm();
  }
};

struct Run {
  dpgen::UnrolledGradient result;
  double nu_adj;
  VectorXd forcing_adj;
};

Run run(Burgers model, const VectorXd& u0, int steps, const Loss& loss,
        const dpgen::CheckpointOptions& options) {
  model.nu_adj = 0.0;
  model.forcing_adj.setZero();
  Run out;
  out.result = dpgen::unrolled_gradient(
      u0, steps, [&](int, const VectorXd& s, VectorXd& next) { model.step(s, next); },
      [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
        model.step_adjoint(s, next_adj, s_adj);
      },
      loss, options);
  out.nu_adj = model.nu_adj;
  out.forcing_adj = model.forcing_adj;
  return out;
}

// The loss by a plain forward run, for finite differences.
double forward_loss(const Burgers& model, VectorXd u, int steps, const Loss& loss) {
  VectorXd scratch(u.size()), next(u.size());
  double total = loss(0, u, scratch);
  for (int t = 0; t < steps; ++t) {
    model.step(u, next);
    u.swap(next);
    total += loss(t + 1, u, scratch);
  }
  return total;
}

bool same_bits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

dpgen::CheckpointOptions full_tape() { return {}; }
dpgen::CheckpointOptions revolve(int snapshots) {
  dpgen::CheckpointOptions options;
  options.strategy = dpgen::CheckpointStrategy::revolve;
  options.snapshots = snapshots;
  return options;
}

// Independent references for Revolve's step count. (1) The dynamic programme over every
// schedule: reversing l steps from a stored state with s snapshots (the stored one included)
// either recomputes from the start every time (s = 1), or advances m steps, stores that state,
// reverses the tail with s - 1 snapshots and then the head with s.
struct RevolveTable {
  int max_steps, max_snapshots;
  std::vector<long long> cost;
  RevolveTable(int steps, int snapshots)
      : max_steps(steps), max_snapshots(snapshots),
        cost(static_cast<std::size_t>((steps + 1) * (snapshots + 1)), 0) {
    for (int s = 1; s <= snapshots; ++s)
      for (int l = 2; l <= steps; ++l) {
        long long best = static_cast<long long>(l) * (l - 1) / 2;
        if (s > 1)
          for (int m = 1; m < l; ++m)
            best = std::min(best, m + at(l - m, s - 1) + at(m, s));
        at(l, s) = best;
      }
  }
  long long& at(int l, int s) {
    return cost[static_cast<std::size_t>(l * (max_snapshots + 1) + s)];
  }
};

// (2) Griewank's closed form t(l, s) = r l - beta(s + 1, r - 1), beta(s, r) = C(s + r, s),
// r minimal with l <= beta(s, r); binomials evaluated in floating point here.
long long griewank(long long l, long long s) {
  if (l <= 1)
    return 0;
  const auto beta = [](long long ss, long long r) {
    return std::llround(
        std::exp(std::lgamma(ss + r + 1.0) - std::lgamma(ss + 1.0) - std::lgamma(r + 1.0)));
  };
  long long r = 0;
  while (beta(s, r) < l)
    ++r;
  return r * l - beta(s + 1, r - 1);
}

} // namespace

TEST_CASE("Griewank's closed form equals the optimal schedule's cost") {
  RevolveTable table(80, 8);
  for (int s = 1; s <= 8; ++s)
    for (int l = 1; l <= 80; ++l) {
      CAPTURE(l);
      CAPTURE(s);
      REQUIRE(dpgen::revolve_forward_steps(l, s) == table.at(l, s));
      REQUIRE(griewank(l, s) == table.at(l, s));
    }
  CHECK(dpgen::revolve_forward_steps(4000, 16) == griewank(4000, 16));
  CHECK(dpgen::revolve_forward_steps(1000000, 3) == griewank(1000000, 3));
}

TEST_CASE("full tape and Revolve give bit-identical gradients on a nonlinear step") {
  const Burgers model;
  const VectorXd u0 = model.initial_state();
  const int steps = 100;
  RevolveTable table(steps, 12);
  for (LossKind kind : {LossKind::final_only, LossKind::several_times, LossKind::trajectory}) {
    const Loss loss{kind, steps};
    const Run full = run(model, u0, steps, loss, full_tape());
    CHECK(full.result.stats.forward_steps == steps);
    CHECK(full.result.stats.recomputed_steps == 0);
    CHECK(full.result.stats.adjoint_steps == steps);
    CHECK(full.result.stats.max_snapshots == steps);
    CHECK(full.result.stats.peak_snapshot_bytes == steps * u0.size() * sizeof(double));
    CHECK(full.result.state_adjoint.norm() > 0.0);

    for (int snapshots : {1, 2, 3, 5, 12, 99, 100, 250}) {
      CAPTURE(snapshots);
      const Run rev = run(model, u0, steps, loss, revolve(snapshots));
      CHECK(same_bits(rev.result.state_adjoint, full.result.state_adjoint));
      CHECK(same_bits(rev.forcing_adj, full.forcing_adj));
      CHECK(same_bits(rev.nu_adj, full.nu_adj));
      CHECK(same_bits(rev.result.loss, full.result.loss));
      CHECK(same_bits(rev.result.final_state, full.result.final_state));

      const dpgen::CheckpointStats& stats = rev.result.stats;
      // Minimal forward steps to reverse, plus the one step that produces s_T.
      const long long minimal = snapshots <= 12 ? table.at(steps, snapshots) : steps - 1;
      CHECK(stats.forward_steps == minimal + 1);
      CHECK(stats.recomputed_steps == minimal + 1 - steps);
      CHECK(stats.adjoint_steps == steps);
      CHECK(stats.max_snapshots <= snapshots);
      CHECK(stats.max_snapshots == std::min(snapshots, steps));
      CHECK(stats.peak_snapshot_bytes == stats.max_snapshots * u0.size() * sizeof(double));
    }
  }
}

TEST_CASE("Revolve's step count follows Griewank's formula for several (T, s)") {
  const Burgers model;
  const VectorXd u0 = model.initial_state();
  for (int steps : {1, 2, 3, 7, 16, 31, 64, 257}) {
    for (int snapshots : {1, 2, 3, 4, 6, 10}) {
      CAPTURE(steps);
      CAPTURE(snapshots);
      const Loss l{LossKind::several_times, steps};
      const Run rev = run(model, u0, steps, l, revolve(snapshots));
      CHECK(rev.result.stats.forward_steps == griewank(steps, snapshots) + 1);
      CHECK(rev.result.stats.max_snapshots <= snapshots);
    }
  }
}

TEST_CASE("the unrolled gradient matches central differences") {
  const Burgers model;
  const VectorXd u0 = model.initial_state();
  const int steps = 30;
  for (LossKind kind : {LossKind::several_times, LossKind::trajectory}) {
    const Loss loss{kind, steps};
    const Run rev = run(model, u0, steps, loss, revolve(4));
    CHECK(rev.result.loss == doctest::Approx(forward_loss(model, u0, steps, loss)).epsilon(1e-14));

    // Directional derivatives: d/de L(u0 + e v) = <dL/du0, v>, and likewise for f; nu directly.
    // Step 1e-5 leaves an O(1e-10) truncation error relative to O(1) derivatives.
    const double eps = 1e-5;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal;
    VectorXd v(u0.size());
    for (Eigen::Index i = 0; i < v.size(); ++i)
      v[i] = normal(rng);
    const double fd_u0 = (forward_loss(model, u0 + eps * v, steps, loss) -
                          forward_loss(model, u0 - eps * v, steps, loss)) /
                         (2.0 * eps);
    CHECK(rev.result.state_adjoint.dot(v) == doctest::Approx(fd_u0).epsilon(1e-7));

    Burgers up = model, down = model;
    up.forcing += eps * v;
    down.forcing -= eps * v;
    const double fd_f =
        (forward_loss(up, u0, steps, loss) - forward_loss(down, u0, steps, loss)) / (2.0 * eps);
    CHECK(rev.forcing_adj.dot(v) == doctest::Approx(fd_f).epsilon(1e-7));

    up = model;
    down = model;
    up.nu += eps * model.nu;
    down.nu -= eps * model.nu;
    const double fd_nu = (forward_loss(up, u0, steps, loss) - forward_loss(down, u0, steps, loss)) /
                         (2.0 * eps * model.nu);
    CHECK(rev.nu_adj == doctest::Approx(fd_nu).epsilon(1e-7));
  }
}

TEST_CASE("edge cases: zero and one step") {
  const Burgers model;
  const VectorXd u0 = model.initial_state();
  const Loss loss{LossKind::trajectory, 0};
  const Run zero = run(model, u0, 0, loss, revolve(1));
  CHECK(zero.result.stats.forward_steps == 0);
  CHECK(same_bits(zero.result.final_state, u0));
  CHECK(zero.result.state_adjoint.isApprox(u0 - loss.target(0, model.n)));

  const Loss loss1{LossKind::final_only, 1};
  const Run one_full = run(model, u0, 1, loss1, full_tape());
  const Run one_rev = run(model, u0, 1, loss1, revolve(1));
  CHECK(one_rev.result.stats.forward_steps == 1);
  CHECK(same_bits(one_full.result.state_adjoint, one_rev.result.state_adjoint));
}

TEST_CASE("memory of a 4000-step unrolled run: full tape vs 16 snapshots") {
  Burgers model;
  model.n = 1024;
  model.dx = 1.0 / 1024;
  model.dt = 1e-4;
  model.nu = 1e-3;
  model.forcing = VectorXd::Zero(1024);
  model.forcing_adj = VectorXd::Zero(1024);
  const VectorXd u0 = model.initial_state();
  const int steps = 4000;
  const Loss loss{LossKind::several_times, steps};
  const Run full = run(model, u0, steps, loss, full_tape());
  const Run rev = run(model, u0, steps, loss, revolve(16));
  CHECK(same_bits(full.result.state_adjoint, rev.result.state_adjoint));
  CHECK(same_bits(full.nu_adj, rev.nu_adj));
  const std::size_t state_bytes = 1024 * sizeof(double);
  CHECK(full.result.stats.peak_snapshot_bytes == steps * state_bytes);
  CHECK(rev.result.stats.peak_snapshot_bytes == 16 * state_bytes);
  CHECK(rev.result.stats.forward_steps == griewank(steps, 16) + 1);
  MESSAGE("4000 steps, n = 1024 doubles (8192 B per state): full tape peak "
          << full.result.stats.peak_snapshot_bytes << " B in " << full.result.stats.max_snapshots
          << " states, " << full.result.stats.forward_steps << " forward steps; revolve(16) peak "
          << rev.result.stats.peak_snapshot_bytes << " B in " << rev.result.stats.max_snapshots
          << " states, " << rev.result.stats.forward_steps << " forward steps ("
          << rev.result.stats.recomputed_steps << " recomputed); working buffers "
          << rev.result.stats.working_bytes << " B in both");
}

#if defined(__SANITIZE_ADDRESS__)
#define DPGEN_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DPGEN_TEST_ASAN 1
#endif
#endif
#ifdef DPGEN_TEST_ASAN
// AddressSanitizer brings its own allocator: glibc's mallinfo2 then reports nothing.
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#endif

// Bytes the heap holds right now (small blocks + mmap'ed large ones), as bench/ measures it;
// under AddressSanitizer, the bytes its allocator has handed out and not yet had back.
std::size_t heap_in_use() {
#ifdef DPGEN_TEST_ASAN
  return __sanitizer_get_current_allocated_bytes();
#else
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
#endif
}

// One gradient of L = 1/2 |s_T|^2 with the workspace and result given, returning the most the
// heap held above its level at the call (sampled in every step, adjoint step and loss call) and
// checking it is back at that level after the call.
std::size_t heap_growth_of_call(Burgers& model, const VectorXd& u0, int steps,
                                const dpgen::CheckpointOptions& options,
                                dpgen::CheckpointWorkspace* workspace,
                                dpgen::UnrolledGradient& result) {
  model.nu_adj = 0.0;
  model.forcing_adj.setZero();
  const std::size_t base = heap_in_use();
  std::size_t peak = 0;
  const auto sample = [&] {
    const std::size_t now = heap_in_use();
    peak = std::max(peak, now > base ? now - base : 0);
  };
  dpgen::unrolled_gradient(
      u0, steps,
      [&](int, const VectorXd& s, VectorXd& next) {
        model.step(s, next);
        sample();
      },
      [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
        model.step_adjoint(s, next_adj, s_adj);
        sample();
      },
      [&](int t, const VectorXd& s, VectorXd& s_adj) {
        sample();
        if (t != steps)
          return 0.0;
        s_adj += s;
        return 0.5 * s.squaredNorm();
      },
      options, workspace, result);
  sample();
  return peak;
}

TEST_CASE("a reused workspace: the same bits, and no heap growth from the second call on") {
  // 256 cells: 2 KB per state, blocks that glibc's heap counts as free once freed (smaller ones
  // may sit in its per-thread cache, counted as in use, so their reuse would not show). The
  // sanitizer build counts every block exactly: it found Revolve's frame stack allocated anew in
  // each call (12-96 bytes), now kept in the workspace.
  Burgers model;
  model.n = 256;
  model.dx = 1.0 / 256;
  model.dt = 1e-4;
  model.forcing = VectorXd::Zero(256);
  model.forcing_adj = VectorXd::Zero(256);
  const VectorXd u0 = model.initial_state();
  const int steps = 200;
  const std::size_t tape_bytes = steps * model.n * sizeof(double);
  dpgen::CheckpointOptions assigning = full_tape();
  assigning.step_assigns_every_element = true; // Burgers::step writes every cell
  dpgen::CheckpointOptions assigning_revolve = revolve(7);
  assigning_revolve.step_assigns_every_element = true;
  for (const dpgen::CheckpointOptions& options :
       {full_tape(), revolve(7), revolve(1), revolve(500), assigning, assigning_revolve}) {
    CAPTURE(options.snapshots);
    CAPTURE(options.step_assigns_every_element);
    // Without a workspace every call allocates its stored states again (this is what the
    // sampling sees, so the zero below is not for want of looking).
    dpgen::UnrolledGradient plain;
    heap_growth_of_call(model, u0, steps, options, nullptr, plain);
    const std::size_t fresh = heap_growth_of_call(model, u0, steps, options, nullptr, plain);
    CHECK(fresh >= static_cast<std::size_t>(plain.stats.max_snapshots) * model.n * sizeof(double));
    const double nu_adj = model.nu_adj;
    const VectorXd forcing_adj = model.forcing_adj;

    dpgen::CheckpointWorkspace workspace;
    dpgen::UnrolledGradient reused;
    heap_growth_of_call(model, u0, steps, options, &workspace, reused); // sizes the buffers
    for (int call = 2; call <= 3; ++call) {
      CAPTURE(call);
      CHECK(heap_growth_of_call(model, u0, steps, options, &workspace, reused) == 0);
      CHECK(same_bits(reused.state_adjoint, plain.state_adjoint));
      CHECK(same_bits(reused.final_state, plain.final_state));
      CHECK(same_bits(reused.loss, plain.loss));
      CHECK(same_bits(model.nu_adj, nu_adj));
      CHECK(same_bits(model.forcing_adj, forcing_adj));
      CHECK(reused.stats.forward_steps == plain.stats.forward_steps);
      CHECK(reused.stats.peak_snapshot_bytes == plain.stats.peak_snapshot_bytes);
    }
    if (options.strategy == dpgen::CheckpointStrategy::full_tape)
      CHECK(workspace.bytes() >= tape_bytes);
  }
}

TEST_CASE("a workspace follows a change of size and step count") {
  Burgers small;
  Burgers large;
  large.n = 96;
  large.dx = 1.0 / 96;
  large.forcing = VectorXd::Zero(96);
  large.forcing_adj = VectorXd::Zero(96);
  dpgen::CheckpointWorkspace workspace;
  for (Burgers* model : {&small, &large, &small}) {
    const VectorXd u0 = model->initial_state();
    for (int steps : {30, 5, 0, 1}) {
      const Loss loss{LossKind::several_times, steps};
      for (const dpgen::CheckpointOptions& options : {full_tape(), revolve(3)}) {
        const Run expected = run(*model, u0, steps, loss, options);
        Burgers m = *model;
        m.nu_adj = 0.0;
        const dpgen::UnrolledGradient got = dpgen::unrolled_gradient(
            u0, steps, [&](int, const VectorXd& s, VectorXd& next) { m.step(s, next); },
            [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
              m.step_adjoint(s, next_adj, s_adj);
            },
            loss, options, &workspace);
        CHECK(same_bits(got.state_adjoint, expected.result.state_adjoint));
        CHECK(same_bits(m.nu_adj, expected.nu_adj));
      }
    }
  }
}

TEST_CASE("checkpoint errors") {
  const Burgers model;
  const VectorXd u0 = model.initial_state();
  const Loss loss{LossKind::final_only, 5};
  CHECK_THROWS_WITH_AS(run(model, u0, 5, loss, revolve(0)),
                       "checkpoint: revolve needs at least 1 snapshot (got 0)",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::revolve_forward_steps(10, 0),
                       "checkpoint: revolve needs at least 1 snapshot (got 0)",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(run(model, u0, -1, loss, full_tape()),
                       "checkpoint: the number of steps must be >= 0 (got -1)",
                       std::invalid_argument);
  VectorXd bad = u0;
  bad[4] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(run(model, bad, 5, loss, full_tape()),
                       "checkpoint: initial state contains nan at index 4", std::invalid_argument);
  const auto shrinking = [](int t, const VectorXd& s, VectorXd& next) {
    next = t == 3 ? s.head(5) : s;
  };
  const auto no_adjoint = [](int, const VectorXd&, const VectorXd&, VectorXd&) {};
  for (const dpgen::CheckpointOptions& options : {full_tape(), revolve(2)})
    CHECK_THROWS_WITH_AS(dpgen::unrolled_gradient(u0, 6, shrinking, no_adjoint, loss, options),
                         "checkpoint: step 3 returned a state of size 5, expected 48",
                         std::invalid_argument);
}
