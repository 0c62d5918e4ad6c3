// The training loop: an optimizer applied to a loss+gradient callable, with per-iteration
// progress (an observer callback; the examples' CSV log hooks in there), stopping rules, and a
// hard stop on NaN or Inf. Like all of the runtime, it writes no files.
#pragma once

#include "dpgen/error.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/termination.hpp"

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace dpgen {

/// One row of progress: the state after `iteration` updates (0 = before the first update).
struct TrainProgress {
  int iteration = 0;
  double loss = 0.0;
  double grad_norm = 0.0; ///< Euclidean norm of dL/dx
  double seconds = 0.0;   ///< wall time of this iteration (its update and evaluations)
  int evaluations = 0;    ///< evaluations of the loss in this iteration
};

/// Settings of train().
struct TrainOptions {
  /// Largest number of updates (>= 0).
  int max_iterations = 100;
  /// Stop when the gradient norm is at most this (checked at every row, iteration 0 included).
  double gradient_tolerance = 0.0;
  /// Stop when the loss is at most this.
  double loss_tolerance = -std::numeric_limits<double>::infinity();
  /// Stop when the wall time of the run reaches this many seconds (checked at every row).
  double time_limit = std::numeric_limits<double>::infinity();
  /// The observer: called once per row, in order, iteration 0 (the starting point) first, also
  /// for the last row and for a non-finite one (before train() stops on it). Logging hooks in
  /// here (the examples' CSV log: examples/common/csv_log.hpp); train() itself writes nothing.
  std::function<void(const TrainProgress&)> callback;
  /// Throw TrainingError (carrying the summary) when a loss or gradient is not finite;
  /// otherwise only the summary reports it (termination loss_not_finite or
  /// gradient_not_finite, x holding the offending iterate).
  bool throw_on_failure = true;
  /// The norm of a gradient, for the progress rows and gradient_tolerance. Empty: the Euclidean
  /// norm of the vector. A distributed run, where each rank holds a block of the parameters,
  /// passes the norm reduced over the ranks (dpgen::mpi::Decomposition::norm), so every rank
  /// reports, and stops on, the same global value.
  std::function<double(const Eigen::VectorXd&)> norm;
};

/// What train() did (seconds: the sum of the rows' times).
struct TrainSummary : MinimizerSummary {
  double final_grad_norm = 0.0;
  int evaluations = 0; ///< evaluations of the loss in all
};

/// Thrown when the loss or the gradient is not finite; says which and at which iteration, and
/// carries the run's summary (termination loss_not_finite or gradient_not_finite).
class TrainingError : public OptimizationError {
public:
  explicit TrainingError(const MinimizerSummary& summary) : OptimizationError(summary) {}
  /// The iteration whose loss or gradient was not finite.
  int iteration() const { return summary().iterations; }
};

/// Minimises f from x (updated in place) with `optimizer`. Evaluates f at x first (iteration
/// 0), then performs up to options.max_iterations updates, reporting each row to the callback
/// and stopping early on the gradient or loss tolerance or the time limit. As soon as a loss or
/// gradient is not finite it stops (x then holds the offending iterate) and throws
/// TrainingError ("training: loss is NaN at iteration 7"), or only reports it in the summary
/// when options.throw_on_failure is off. Throws std::invalid_argument when f returns a gradient
/// of the wrong size. Errors of f and of the optimizer propagate unchanged.
inline TrainSummary train(const LossGradient& f, Optimizer& optimizer, Eigen::VectorXd& x,
                          const TrainOptions& options = {}) {
  using clock = std::chrono::steady_clock;
  if (options.max_iterations < 0)
    throw std::invalid_argument(detail::message("training: max_iterations must be >= 0 (got ",
                                                options.max_iterations, ")"));
  detail::require_finite(x, "training", "initial parameter vector");
  TrainSummary summary;
  Eigen::VectorXd grad = Eigen::VectorXd::Zero(x.size());
  const clock::time_point run_start = clock::now();

  // Checks and reports one row; returns false (termination and message set) on NaN/Inf.
  const auto report = [&](TrainProgress progress, const clock::time_point start) {
    progress.seconds = std::chrono::duration<double>(clock::now() - start).count();
    if (grad.size() != x.size())
      throw std::invalid_argument(detail::message("training: gradient has size ", grad.size(),
                                                  ", expected ", x.size(), " at iteration ",
                                                  progress.iteration));
    progress.grad_norm = options.norm ? options.norm(grad) : grad.norm();
    summary.seconds += progress.seconds;
    summary.evaluations += progress.evaluations;
    summary.final_loss = progress.loss;
    summary.final_grad_norm = progress.grad_norm;
    if (options.callback)
      options.callback(progress);
    if (!std::isfinite(progress.loss)) {
      summary.termination = Termination::loss_not_finite;
      summary.message =
          detail::message("training: loss is ", std::isnan(progress.loss) ? "NaN" : "Inf",
                          " at iteration ", progress.iteration);
      return false;
    }
    const Eigen::Index bad = detail::first_non_finite(grad);
    if (bad >= 0) {
      summary.termination = Termination::gradient_not_finite;
      summary.message =
          detail::message("training: gradient is ", std::isnan(grad[bad]) ? "NaN" : "Inf",
                          " at iteration ", progress.iteration, " (index ", bad, ")");
      return false;
    }
    if (!std::isfinite(progress.grad_norm)) { // a reduced norm: NaN on every rank
      summary.termination = Termination::gradient_not_finite;
      summary.message = detail::message("training: gradient norm is ",
                                        std::isnan(progress.grad_norm) ? "NaN" : "Inf",
                                        " at iteration ", progress.iteration);
      return false;
    }
    return true;
  };
  // Whether a stopping rule holds after a finite row (sets the termination).
  const auto stop = [&]() {
    if (summary.final_grad_norm <= options.gradient_tolerance) {
      summary.termination = Termination::gradient_tolerance;
      return true;
    }
    if (summary.final_loss <= options.loss_tolerance) {
      summary.termination = Termination::loss_tolerance;
      return true;
    }
    if (std::chrono::duration<double>(clock::now() - run_start).count() >= options.time_limit) {
      summary.termination = Termination::time_limit;
      return true;
    }
    return false;
  };

  TrainProgress progress;
  clock::time_point start = clock::now();
  progress.loss = f(x, grad);
  progress.evaluations = 1;
  bool finite = report(progress, start);
  summary.initial_loss = summary.final_loss;
  bool stopped = !finite || stop();
  for (int iteration = 1; !stopped && iteration <= options.max_iterations; ++iteration) {
    start = clock::now();
    progress.iteration = iteration;
    progress.evaluations = optimizer.step(x, progress.loss, grad, f);
    summary.iterations = iteration;
    finite = report(progress, start);
    stopped = !finite || stop();
  }
  if (!stopped)
    summary.termination = Termination::max_iterations;

  const std::string who = detail::message("training (", optimizer.name(), "): ");
  switch (summary.termination) {
  case Termination::max_iterations:
    summary.message =
        detail::message(who, "stopped after ", summary.iterations, " iterations (the limit), loss ",
                        summary.final_loss, ", gradient norm ", summary.final_grad_norm);
    break;
  case Termination::gradient_tolerance:
    summary.message =
        detail::message(who, "converged after ", summary.iterations, " iterations, gradient norm ",
                        summary.final_grad_norm, " <= tolerance ", options.gradient_tolerance);
    break;
  case Termination::loss_tolerance:
    summary.message =
        detail::message(who, "converged after ", summary.iterations, " iterations, loss ",
                        summary.final_loss, " <= tolerance ", options.loss_tolerance);
    break;
  case Termination::time_limit:
    summary.message = detail::message(
        who, "stopped after ", summary.iterations, " iterations (time limit ", options.time_limit,
        " s reached), loss ", summary.final_loss, ", gradient norm ", summary.final_grad_norm);
    break;
  default: // loss_not_finite, gradient_not_finite: the message is set
    if (options.throw_on_failure)
      throw TrainingError(summary);
    break;
  }
  return summary;
}

} // namespace dpgen
