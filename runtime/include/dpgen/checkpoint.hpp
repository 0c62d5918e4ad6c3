// Reverse-mode gradients through unrolled time loops s_{t+1} = step(t, s_t): store every
// state (full tape) or binomial checkpointing (Revolve, Griewank & Walther) with s snapshots.
#pragma once

#include "dpgen/error.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace dpgen {

/// How the states needed by the reverse sweep are kept.
enum class CheckpointStrategy {
  full_tape, ///< store s_0 .. s_{T-1} during one forward sweep: T states, no recomputation
  revolve,   ///< keep at most `snapshots` states and recompute the rest (binomial schedule)
};

/// Settings of unrolled_gradient.
struct CheckpointOptions {
  CheckpointStrategy strategy = CheckpointStrategy::full_tape;
  /// Revolve only: the most states held at once, the initial state's copy included (>= 1).
  /// With snapshots >= steps Revolve stores every state and recomputes nothing.
  int snapshots = 0;
  /// True when step() assigns every element of s_next: s_next then arrives sized but not
  /// zero-filled (its contents are stale), which saves one write of the state per step. Leave
  /// false for a step that accumulates into s_next or writes only part of it.
  bool step_assigns_every_element = false;
};

/// The buffers of unrolled_gradient: the stored states (the tape, or Revolve's snapshots) and the
/// forward and adjoint work vectors. Pass one to every call of a training loop so that calls
/// after the first reuse its storage instead of allocating (and page-faulting) the whole tape
/// again: from the second call with the same sizes on, unrolled_gradient allocates nothing but
/// the result's two vectors (none at all with the overload that fills a given result). Its
/// contents between calls are meaningless; one workspace must not serve two calls at once.
struct CheckpointWorkspace {
  /// One frame of Revolve's schedule: reverse steps [t0, t0 + l) from the base snapshot s_t0,
  /// with at most s snapshots (the base included).
  struct Frame {
    int t0, l, s;
  };
  std::vector<Eigen::VectorXd> states; ///< slots for stored states, kept across calls
  std::vector<Frame> frames;           ///< Revolve's stack of frames, kept across calls
  Eigen::VectorXd cur, next, adj, adj_prev;
  /// Bytes of state storage held (the slots' and the work vectors' capacity).
  std::size_t bytes() const {
    std::size_t total = 0;
    for (const Eigen::VectorXd& v : states)
      total += static_cast<std::size_t>(v.size()) * sizeof(double);
    for (const Eigen::VectorXd* v : {&cur, &next, &adj, &adj_prev})
      total += static_cast<std::size_t>(v->size()) * sizeof(double);
    return total;
  }
};

/// Counters of one unrolled_gradient call.
struct CheckpointStats {
  long long forward_steps = 0;         ///< calls of step(), the first sweep included
  long long recomputed_steps = 0;      ///< forward_steps - steps: the price of checkpointing
  long long adjoint_steps = 0;         ///< calls of step_adjoint() (always = steps)
  int max_snapshots = 0;               ///< most states stored at the same time
  std::size_t peak_snapshot_bytes = 0; ///< most bytes of stored states at the same time
  std::size_t working_bytes = 0;       ///< the fixed buffers besides the stored states (4 n)
};

/// What unrolled_gradient returns.
struct UnrolledGradient {
  double loss = 0.0;             ///< sum of the loss terms returned by loss_adjoint
  Eigen::VectorXd state_adjoint; ///< dL/ds_0
  Eigen::VectorXd final_state;   ///< s_T
  CheckpointStats stats;
};

/// Griewank's minimal number of forward steps ("advances") to reverse `steps` steps while
/// holding at most `snapshots` states (the initial one included):
///   t(l, s) = r l - beta(s + 1, r - 1),  beta(s, r) = C(s + r, s),
/// with r the smallest integer such that l <= beta(s, r). unrolled_gradient with Revolve calls
/// step() exactly t(steps, snapshots) + 1 times: the extra step produces s_T for the terminal
/// loss (the adjoint steps need only s_t, not a recorded forward step).
inline long long revolve_forward_steps(long long steps, long long snapshots) {
  if (snapshots < 1)
    throw std::invalid_argument(
        detail::message("checkpoint: revolve needs at least 1 snapshot (got ", snapshots, ")"));
  if (steps <= 1)
    return 0;
  long long r = 0;
  long long beta = 1; // beta(s, 0) = 1
  while (beta < steps) {
    ++r;
    beta = beta * (snapshots + r) / r; // beta(s, r) = beta(s, r - 1) (s + r) / r
  }
  // beta(s + 1, r - 1) = C(s + r, r - 1) = beta(s, r) r / (s + 1)
  return r * steps - beta * r / (snapshots + 1);
}

namespace detail {

// The first step of an optimal split of l steps with s >= 2 snapshots: advance m steps, store
// that state, reverse the last l - m steps with s - 1 snapshots, then the first m with s. The
// cost g(m) = m + t(l - m, s - 1) + t(m, s) is convex in m (t(., s) has non-decreasing
// increments r), so the smallest minimiser is found by bisection on g(m + 1) - g(m) >= 0.
inline long long revolve_split(long long l, long long s) {
  const auto cost = [&](long long m) {
    return m + revolve_forward_steps(l - m, s - 1) + revolve_forward_steps(m, s);
  };
  long long lo = 1, hi = l - 1; // the minimiser lies in [lo, hi]
  while (lo < hi) {
    const long long mid = lo + (hi - lo) / 2;
    if (cost(mid + 1) - cost(mid) >= 0)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

// Asks the caches for a small stored state that the reverse sweep reads next: the forward sweep
// wrote it long before (the tape of 10^4 steps of 256 cells is 20 MB), and the hardware
// prefetcher needs several misses per 4 KiB page before it runs ahead, which for a state of a
// few pages is most of its lines. Measured on the 2-core AMD EPYC VM (upwind, full tape, adjoint
// step per cell): 2.83 -> 2.05 ns at 256 cells, 2.63 -> 2.40 at 1024, 2.46 -> 2.38 at 4096. From
// 8192 cells it costs up to 10% (the adjoint then runs on both cores, and the prefetcher has
// pages to learn from): states above 32 KiB are left alone.
inline void prefetch_small_state(const Eigen::VectorXd& v) {
#if defined(__GNUC__)
  constexpr std::size_t kMaxBytes = 32768;
  constexpr std::size_t kLine = 64;
  const std::size_t bytes = static_cast<std::size_t>(v.size()) * sizeof(double);
  if (bytes > kMaxBytes)
    return;
  const char* p = reinterpret_cast<const char*>(v.data());
  for (std::size_t offset = 0; offset < bytes; offset += kLine)
    __builtin_prefetch(p + offset);
#else
  (void)v;
#endif
}

} // namespace detail

/// Runs s_{t+1} = step(t, s_t) for t = 0 .. steps-1 from `initial_state` and returns the loss
/// L = sum_t l_t(s_t) with its gradient dL/ds_0, in `result` (its vectors are reused when they
/// have the right size already). The callables, all on Eigen::VectorXd:
///  - `step(t, s_t, s_next)`: s_next arrives sized like s_t, zero-filled (stale, with
///    options.step_assigns_every_element); must be deterministic (the reverse sweep may
///    recompute states and relies on getting the same bits).
///  - `step_adjoint(t, s_t, next_adj, s_adj)`: ADD (d s_{t+1}/d s_t)^T next_adj into s_adj
///    (zero-filled), and add the parameter adjoints of this step into the caller's own
///    accumulators (a generated kernel adjoint does both). Called once per t, t = steps-1 .. 0.
///  - `loss_adjoint(t, s_t, s_adj)`: return the loss term l_t(s_t) and ADD dl_t/ds_t into
///    s_adj; return 0 and add nothing at times without a loss. Called once per t,
///    t = steps .. 0, after step_adjoint(t).
/// Both strategies make the same calls in the same order with the same states, so their
/// results are identical bit for bit, with or without a workspace. `workspace` (may be null:
/// buffers of this call only) keeps the tape and the work vectors between calls. Throws
/// std::invalid_argument for a negative step count, fewer than 1 Revolve snapshot, a
/// non-finite initial state or a step that changes the state's size.
template <typename Step, typename StepAdjoint, typename LossAdjoint>
void unrolled_gradient(const Eigen::VectorXd& initial_state, int steps, Step&& step,
                       StepAdjoint&& step_adjoint, LossAdjoint&& loss_adjoint,
                       const CheckpointOptions& options, CheckpointWorkspace* workspace,
                       UnrolledGradient& result) {
  using Eigen::VectorXd;
  const bool revolve = options.strategy == CheckpointStrategy::revolve;
  if (steps < 0)
    throw std::invalid_argument(
        detail::message("checkpoint: the number of steps must be >= 0 (got ", steps, ")"));
  if (revolve && options.snapshots < 1)
    throw std::invalid_argument(detail::message(
        "checkpoint: revolve needs at least 1 snapshot (got ", options.snapshots, ")"));
  detail::require_finite(initial_state, "checkpoint", "initial state");
  const Eigen::Index n = initial_state.size();
  const std::size_t state_bytes = static_cast<std::size_t>(n) * sizeof(double);

  result.loss = 0.0;
  result.stats = CheckpointStats{};
  CheckpointStats& stats = result.stats;
  stats.working_bytes = 4 * state_bytes;
  CheckpointWorkspace local;
  CheckpointWorkspace& work = workspace != nullptr ? *workspace : local;
  VectorXd& cur = work.cur; // forward work buffers
  VectorXd& next = work.next;
  VectorXd& adj = work.adj;           // dL/ds_{t+1}
  VectorXd& adj_prev = work.adj_prev; // dL/ds_t
  cur.resize(n);
  next.resize(n);
  adj.setZero(n);
  adj_prev.resize(n);

  // The stored states (Revolve's snapshots or the tape) are work.states[0 .. used): a stack
  // whose slots keep their storage when popped, for the next push and the next call. The slot
  // vector gets its final length before any reference into it is taken.
  const std::size_t slots =
      static_cast<std::size_t>(revolve ? std::min(options.snapshots, steps + 1) : steps);
  if (work.states.size() < slots)
    work.states.resize(slots);
  std::size_t used = 0;
  // A new slot on top of the stack, sized n (contents stale).
  const auto push = [&]() -> VectorXd& {
    if (used == work.states.size()) // the schedules above never hold more than `slots` states
      throw std::logic_error("checkpoint: internal error: more states stored than planned");
    VectorXd& slot = work.states[used++];
    slot.resize(n);
    stats.max_snapshots = std::max(stats.max_snapshots, static_cast<int>(used));
    stats.peak_snapshot_bytes = std::max(stats.peak_snapshot_bytes, used * state_bytes);
    return slot;
  };
  const auto top = [&]() -> VectorXd& { return work.states[used - 1]; };
  // out = step(t, in), counted and size-checked.
  const auto forward = [&](int t, const VectorXd& in, VectorXd& out) {
    if (options.step_assigns_every_element)
      out.resize(n);
    else
      out.setZero(n);
    step(t, in, out);
    ++stats.forward_steps;
    if (out.size() != n)
      throw std::invalid_argument(detail::message(
          "checkpoint: step ", t, " returned a state of size ", out.size(), ", expected ", n));
  };
  // cur = s_{t0 + count}, advanced from `from` = s_t0; returns the state (cur, or `from`).
  const auto advance = [&](const VectorXd& from, int t0, int count) -> const VectorXd& {
    if (count == 0)
      return from;
    forward(t0, from, cur);
    for (int t = t0 + 1; t < t0 + count; ++t) {
      forward(t, cur, next);
      cur.swap(next);
    }
    return cur;
  };
  // The reverse sweep's unit: adj = dL/ds_{t+1} in, dL/ds_t out. At t = steps - 1 (always the
  // first leaf) it first computes s_T and seeds the terminal loss.
  const auto leaf = [&](int t, const VectorXd& s_t) {
    if (t == steps - 1) {
      forward(t, s_t, next);
      result.final_state = next;
      result.loss += loss_adjoint(steps, static_cast<const VectorXd&>(result.final_state), adj);
    }
    adj_prev.setZero(n);
    step_adjoint(t, s_t, static_cast<const VectorXd&>(adj), adj_prev);
    ++stats.adjoint_steps;
    result.loss += loss_adjoint(t, s_t, adj_prev);
    adj.swap(adj_prev);
  };

  if (steps == 0) {
    result.final_state = initial_state;
    result.loss += loss_adjoint(0, initial_state, adj);
  } else if (!revolve) {
    // Full tape: one forward sweep storing s_0 .. s_{T-1}, then the reverse sweep reads them.
    push() = initial_state;
    for (int t = 1; t < steps; ++t) {
      VectorXd& out = push();
      forward(t - 1, work.states[used - 2], out);
    }
    for (int t = steps - 1; t >= 0; --t) {
      if (t > 0)
        detail::prefetch_small_state(work.states[t - 1]); // the next leaf's, while this one runs
      leaf(t, work.states[t]);
    }
    used = 0;
  } else {
    // Revolve, as an explicit stack of frames so that the depth of the schedule never touches
    // the call stack. A frame reverses steps [t0, t0 + l) from its base snapshot s_t0 (the top
    // of the stored states while the frame is active), using at most s snapshots, the base
    // included. The stack lives in the workspace: a reused one keeps its capacity.
    using Frame = CheckpointWorkspace::Frame;
    std::vector<Frame>& frames = work.frames;
    frames.clear();
    frames.push_back(Frame{0, steps, options.snapshots});
    push() = initial_state;
    while (!frames.empty()) {
      Frame& f = frames.back();
      const VectorXd& base = top();
      if (f.l == 0) { // done: release the base snapshot
        frames.pop_back();
        --used;
      } else if (f.l == 1) {
        leaf(f.t0, base);
        f.l = 0;
      } else if (f.s == 1) {
        // Only the base: recompute each state from it, l (l - 1) / 2 steps.
        for (int t = f.t0 + f.l - 1; t >= f.t0; --t)
          leaf(t, advance(base, f.t0, t - f.t0));
        f.l = 0;
      } else if (f.s >= f.l) {
        // Room for every state: store s_{t0+1} .. s_{t0+l-1} on the way, l - 1 steps.
        const int t0 = f.t0, l = f.l;
        for (int t = t0; t < t0 + l - 1; ++t) {
          VectorXd& out = push();
          forward(t, work.states[used - 2], out);
        }
        for (int t = t0 + l - 1; t > t0; --t) {
          detail::prefetch_small_state(work.states[used - 2]); // the next leaf's
          leaf(t, top());
          --used;
        }
        leaf(t0, top());
        frames.back().l = 0;
      } else {
        // Advance m steps, store s_{t0+m}, reverse the tail with one snapshot fewer, then
        // (when the tail frame is done) the head [t0, t0 + m) with this frame's snapshots.
        const int m = static_cast<int>(detail::revolve_split(f.l, f.s));
        const Frame tail{f.t0 + m, f.l - m, f.s - 1};
        f.l = m;
        const VectorXd& state = advance(base, f.t0, m); // cur: m >= 1
        push() = state;
        frames.push_back(tail);
      }
    }
  }
  stats.recomputed_steps = stats.forward_steps - steps;
  result.state_adjoint = adj; // a copy: adj stays in the workspace
}

/// The same, returning a new result (its state adjoint and final state are new vectors).
template <typename Step, typename StepAdjoint, typename LossAdjoint>
UnrolledGradient unrolled_gradient(const Eigen::VectorXd& initial_state, int steps, Step&& step,
                                   StepAdjoint&& step_adjoint, LossAdjoint&& loss_adjoint,
                                   const CheckpointOptions& options = {},
                                   CheckpointWorkspace* workspace = nullptr) {
  UnrolledGradient result;
  unrolled_gradient(initial_state, steps, std::forward<Step>(step),
                    std::forward<StepAdjoint>(step_adjoint),
                    std::forward<LossAdjoint>(loss_adjoint), options, workspace, result);
  return result;
}

} // namespace dpgen
