// The training loop: an optimizer applied to a loss+gradient callable, with per-iteration
// progress (callback and CSV log), stopping rules, and a hard stop on NaN or Inf.
#pragma once

#include "dpgen/error.hpp"
#include "dpgen/optim.hpp"

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>

namespace dpgen {

/// One row of progress: the state after `iteration` updates (0 = before the first update).
struct TrainProgress {
  int iteration = 0;
  double loss = 0.0;
  double grad_norm = 0.0; ///< Euclidean norm of dL/dx
  double seconds = 0.0;   ///< wall time of this iteration (its update and evaluations)
  int evaluations = 0;    ///< evaluations of the loss in this iteration
};

/// Why train() stopped.
enum class TrainTermination {
  max_iterations,     ///< the iteration limit was reached
  gradient_tolerance, ///< |grad| <= gradient_tolerance
  loss_tolerance,     ///< loss <= loss_tolerance
};

/// Settings of train().
struct TrainOptions {
  /// Largest number of updates (>= 0).
  int max_iterations = 100;
  /// Stop when the gradient norm is at most this (checked at every row, iteration 0 included).
  double gradient_tolerance = 0.0;
  /// Stop when the loss is at most this.
  double loss_tolerance = -std::numeric_limits<double>::infinity();
  /// When not empty, a CSV log with the header `iter,loss,grad_norm,seconds` and one row per
  /// iteration, iter 0 being the state before the first update. Rows go to `<csv_path>.partial`,
  /// flushed line by line; when train() returns or throws, that file is renamed to csv_path
  /// (replacing an older log). So csv_path only ever holds a finished run's complete log
  /// (ending with the offending row when the run stopped on NaN/Inf), and a process killed
  /// mid-run leaves `<csv_path>.partial`, not a truncated or stale file that looks finished.
  std::string csv_path;
  /// Called after every row (also the last one and a non-finite one) with its progress.
  std::function<void(const TrainProgress&)> callback;
  /// The norm of a gradient, for the progress rows and gradient_tolerance. Empty: the Euclidean
  /// norm of the vector. A distributed run, where each rank holds a block of the parameters,
  /// passes the norm reduced over the ranks (dpgen::mpi::Decomposition::norm), so every rank
  /// reports, and stops on, the same global value.
  std::function<double(const Eigen::VectorXd&)> norm;
};

/// What train() did.
struct TrainSummary {
  int iterations = 0; ///< updates performed
  double initial_loss = 0.0;
  double final_loss = 0.0;
  double final_grad_norm = 0.0;
  double total_seconds = 0.0;
  int evaluations = 0; ///< evaluations of the loss in all
  TrainTermination termination = TrainTermination::max_iterations;
  std::string message; ///< one line saying why it stopped
};

/// Thrown when the loss or the gradient is not finite; says which and at which iteration.
class TrainingError : public std::runtime_error {
public:
  TrainingError(const std::string& what, int iteration)
      : std::runtime_error(what), iteration_(iteration) {}
  /// The iteration whose loss or gradient was not finite.
  int iteration() const { return iteration_; }

private:
  int iteration_;
};

namespace detail {

// The CSV log: rows into <path>.partial, flushed per line, renamed to <path> when closed.
class CsvLog {
public:
  explicit CsvLog(const std::string& path) : path_(path), partial_(path + ".partial") {
    if (path_.empty())
      return;
    out_.open(partial_, std::ios::out | std::ios::trunc);
    if (!out_)
      throw std::runtime_error(
          message("training: cannot open log file '", partial_, "' for writing"));
    out_ << "iter,loss,grad_norm,seconds\n" << std::flush;
  }
  CsvLog(const CsvLog&) = delete;
  CsvLog& operator=(const CsvLog&) = delete;
  ~CsvLog() {
    if (out_.is_open()) { // an exception is on its way: publish what was logged, quietly
      out_.close();
      std::error_code ignored;
      std::filesystem::rename(partial_, path_, ignored);
    }
  }

  void row(const TrainProgress& p) {
    if (path_.empty())
      return;
    char line[128];
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.9g\n", p.iteration, p.loss, p.grad_norm,
                  p.seconds);
    out_ << line << std::flush;
    if (!out_)
      throw std::runtime_error(message("training: writing log file '", partial_, "' failed"));
  }

  void close() {
    if (path_.empty())
      return;
    out_.close();
    std::error_code error;
    std::filesystem::rename(partial_, path_, error);
    if (error)
      throw std::runtime_error(
          message("training: cannot rename '", partial_, "' to '", path_, "': ", error.message()));
  }

private:
  std::string path_, partial_;
  std::ofstream out_;
};

} // namespace detail

/// Minimises f from x (updated in place) with `optimizer`. Evaluates f at x first (iteration
/// 0), then performs up to options.max_iterations updates, reporting each row to the callback
/// and the CSV log and stopping early on the gradient or loss tolerance. Throws TrainingError
/// ("training: loss is NaN at iteration 7") as soon as a loss or gradient is not finite (x then
/// holds the offending iterate), and std::invalid_argument when f returns a gradient of the
/// wrong size. Errors of f and of the optimizer propagate unchanged.
inline TrainSummary train(const LossGradient& f, Optimizer& optimizer, Eigen::VectorXd& x,
                          const TrainOptions& options = {}) {
  using clock = std::chrono::steady_clock;
  if (options.max_iterations < 0)
    throw std::invalid_argument(detail::message("training: max_iterations must be >= 0 (got ",
                                                options.max_iterations, ")"));
  detail::require_finite(x, "training", "initial parameter vector");
  detail::CsvLog log(options.csv_path);
  TrainSummary summary;
  Eigen::VectorXd grad = Eigen::VectorXd::Zero(x.size());

  // Checks, logs and reports one row; throws on NaN/Inf after logging it.
  const auto report = [&](TrainProgress progress, const clock::time_point start) {
    progress.seconds = std::chrono::duration<double>(clock::now() - start).count();
    if (grad.size() != x.size())
      throw std::invalid_argument(detail::message("training: gradient has size ", grad.size(),
                                                  ", expected ", x.size(), " at iteration ",
                                                  progress.iteration));
    progress.grad_norm = options.norm ? options.norm(grad) : grad.norm();
    summary.total_seconds += progress.seconds;
    summary.evaluations += progress.evaluations;
    log.row(progress);
    if (options.callback)
      options.callback(progress);
    if (!std::isfinite(progress.loss))
      throw TrainingError(detail::message("training: loss is ",
                                          std::isnan(progress.loss) ? "NaN" : "Inf",
                                          " at iteration ", progress.iteration),
                          progress.iteration);
    const Eigen::Index bad = detail::first_non_finite(grad);
    if (bad >= 0)
      throw TrainingError(detail::message("training: gradient is ",
                                          std::isnan(grad[bad]) ? "NaN" : "Inf", " at iteration ",
                                          progress.iteration, " (index ", bad, ")"),
                          progress.iteration);
    if (!std::isfinite(progress.grad_norm)) // a reduced norm: NaN on every rank
      throw TrainingError(detail::message("training: gradient norm is ",
                                          std::isnan(progress.grad_norm) ? "NaN" : "Inf",
                                          " at iteration ", progress.iteration),
                          progress.iteration);
    summary.final_loss = progress.loss;
    summary.final_grad_norm = progress.grad_norm;
  };
  const auto converged = [&]() {
    if (summary.final_grad_norm <= options.gradient_tolerance) {
      summary.termination = TrainTermination::gradient_tolerance;
      return true;
    }
    if (summary.final_loss <= options.loss_tolerance) {
      summary.termination = TrainTermination::loss_tolerance;
      return true;
    }
    return false;
  };

  TrainProgress progress;
  clock::time_point start = clock::now();
  progress.loss = f(x, grad);
  progress.evaluations = 1;
  report(progress, start);
  summary.initial_loss = summary.final_loss;
  bool stopped = converged();
  for (int iteration = 1; !stopped && iteration <= options.max_iterations; ++iteration) {
    start = clock::now();
    progress.iteration = iteration;
    progress.evaluations = optimizer.step(x, progress.loss, grad, f);
    summary.iterations = iteration;
    report(progress, start);
    stopped = converged();
  }
  if (!stopped)
    summary.termination = TrainTermination::max_iterations;
  log.close();

  switch (summary.termination) {
  case TrainTermination::max_iterations:
    summary.message =
        detail::message("training (", optimizer.name(), "): stopped after ", summary.iterations,
                        " iterations (the limit), loss ", summary.final_loss, ", gradient norm ",
                        summary.final_grad_norm);
    break;
  case TrainTermination::gradient_tolerance:
    summary.message =
        detail::message("training (", optimizer.name(), "): converged after ", summary.iterations,
                        " iterations, gradient norm ", summary.final_grad_norm, " <= tolerance ",
                        options.gradient_tolerance);
    break;
  case TrainTermination::loss_tolerance:
    summary.message = detail::message("training (", optimizer.name(), "): converged after ",
                                      summary.iterations, " iterations, loss ", summary.final_loss,
                                      " <= tolerance ", options.loss_tolerance);
    break;
  }
  return summary;
}

} // namespace dpgen
