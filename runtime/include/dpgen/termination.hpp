// Why a minimizer stopped, shared by every optimizer entry point (train, lbfgs_minimize,
// hig_minimize, pg_minimize), with the summary fields they all report and the error they throw
// when a run fails.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace dpgen {

/// Why a minimizer stopped. The first group are successes (converged()), max_iterations and
/// time_limit are budgets running out, the rest are failures (failed()), which throw an
/// OptimizationError carrying the summary unless the options' throw_on_failure is off.
enum class Termination {
  max_iterations,      ///< the iteration limit was reached
  gradient_tolerance,  ///< converged: the gradient norm reached its tolerance
  loss_tolerance,      ///< converged: the loss reached its tolerance
  step_tolerance,      ///< converged: an update's norm reached its tolerance
  loss_decrease,       ///< converged: the relative loss decrease stalled (L-BFGS past/delta)
  time_limit,          ///< the wall-time limit was reached
  loss_not_finite,     ///< the loss (or a residual it is made of) became NaN or Inf
  gradient_not_finite, ///< the gradient (or a Jacobian, or an update) became NaN or Inf
  line_search_failed,  ///< the line search found no acceptable step
};

/// The enumerator's name, for messages and logs ("max_iterations", "loss_not_finite", ...).
inline const char* to_string(Termination termination) {
  switch (termination) {
  case Termination::max_iterations:
    return "max_iterations";
  case Termination::gradient_tolerance:
    return "gradient_tolerance";
  case Termination::loss_tolerance:
    return "loss_tolerance";
  case Termination::step_tolerance:
    return "step_tolerance";
  case Termination::loss_decrease:
    return "loss_decrease";
  case Termination::time_limit:
    return "time_limit";
  case Termination::loss_not_finite:
    return "loss_not_finite";
  case Termination::gradient_not_finite:
    return "gradient_not_finite";
  case Termination::line_search_failed:
    return "line_search_failed";
  }
  return "unknown";
}

/// A sentence for the reason ("the iteration limit was reached").
inline const char* describe(Termination termination) {
  switch (termination) {
  case Termination::max_iterations:
    return "the iteration limit was reached";
  case Termination::gradient_tolerance:
    return "the gradient norm reached its tolerance";
  case Termination::loss_tolerance:
    return "the loss reached its tolerance";
  case Termination::step_tolerance:
    return "the update norm reached its tolerance";
  case Termination::loss_decrease:
    return "the relative loss decrease fell below its tolerance";
  case Termination::time_limit:
    return "the time limit was reached";
  case Termination::loss_not_finite:
    return "the loss became NaN or Inf";
  case Termination::gradient_not_finite:
    return "the gradient became NaN or Inf";
  case Termination::line_search_failed:
    return "the line search failed";
  }
  return "unknown";
}

/// True for the tolerance-based stops (the run converged).
inline bool converged(Termination termination) {
  return termination == Termination::gradient_tolerance ||
         termination == Termination::loss_tolerance || termination == Termination::step_tolerance ||
         termination == Termination::loss_decrease;
}

/// True for the stops that are errors (NaN/Inf, failed line search).
inline bool failed(Termination termination) {
  return termination == Termination::loss_not_finite ||
         termination == Termination::gradient_not_finite ||
         termination == Termination::line_search_failed;
}

/// What every minimizer reports; TrainSummary, LbfgsSummary, HigSummary and PgSummary extend it.
struct MinimizerSummary {
  int iterations = 0;        ///< updates performed
  double initial_loss = 0.0; ///< the loss at the starting point
  double final_loss = 0.0;   ///< the loss at the returned point (the offending one on failure)
  double seconds = 0.0;      ///< wall time of the whole run
  Termination termination = Termination::max_iterations;
  std::string message; ///< one line saying why it stopped, with numbers

  /// True when a tolerance was reached (see dpgen::converged).
  bool converged() const { return dpgen::converged(termination); }
  /// True when the run stopped on an error (see dpgen::failed).
  bool failed() const { return dpgen::failed(termination); }
};

/// Thrown when an optimizer cannot go on: a failed line search, a NaN or Inf loss, gradient,
/// residual or Jacobian. When thrown by a minimizer (rather than by one Optimizer::step), it
/// carries the run's summary, whose termination says why and whose iterations say when (for
/// L-BFGS, its evaluations: see LbfgsSummary).
class OptimizationError : public std::runtime_error {
public:
  explicit OptimizationError(const std::string& what) : std::runtime_error(what) {}
  explicit OptimizationError(MinimizerSummary summary)
      : std::runtime_error(summary.message), summary_(std::move(summary)), has_summary_(true) {}
  /// The summary of the failed run (default-constructed when has_summary() is false).
  const MinimizerSummary& summary() const { return summary_; }
  bool has_summary() const { return has_summary_; }

private:
  MinimizerSummary summary_;
  bool has_summary_ = false;
};

} // namespace dpgen
