// Physical gradients (PG; the PBDL book's chapters "Physical Gradients" and "Scale-Invariant
// Physics Training"): an update of x through an inverse solver instead of the adjoint,
//   y = P(x),  y' = y - lr (d2L/dy2)^-1 dL/dy  (a Newton step of the loss in y),
//   x' = P^-1(y'; x)                           (the inverse simulator, local around x),
// and a regularized local inverse for linear P with a kernel and its adjoint:
//   x' = x + argmin_d |P d - (y' - P x)|^2 + lambda |d|^2,  by CG on (P^T P + lambda I) d = P^T r.
#pragma once

#include "dpgen/cg.hpp"
#include "dpgen/error.hpp"
#include "dpgen/termination.hpp"

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace dpgen {

/// A problem min_x L(P(x)) with an inverse simulator, as the PG update needs it.
struct PhysicalGradientProblem {
  /// y = P(x).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& x)> forward;
  /// An x' with P(x') = y_target (or near it), found locally around the current x.
  std::function<Eigen::VectorXd(const Eigen::VectorXd& y_target, const Eigen::VectorXd& x)> inverse;
  /// Returns L(y) and writes the Newton step of L in y, (d2L/dy2)^-1 dL/dy, into `newton_step`.
  std::function<double(const Eigen::VectorXd& y, Eigen::VectorXd& newton_step)> loss;
};

/// L(y) = |y - target|^2 with its Newton step y - target (dL/dy = 2 (y - t), d2L/dy2 = 2 I).
inline std::function<double(const Eigen::VectorXd&, Eigen::VectorXd&)>
l2_loss_newton(Eigen::VectorXd target) {
  return [target = std::move(target)](const Eigen::VectorXd& y, Eigen::VectorXd& newton_step) {
    detail::require_size(y.size(), target.size(), "pg", "y");
    newton_step = y - target;
    return newton_step.squaredNorm();
  };
}

/// Settings of the PG update and of pg_minimize.
struct PgOptions {
  /// lr of the Newton step in y, 0 < lr (1: aim at the loss minimum in y at once).
  double learning_rate = 1.0;
  /// pg_minimize: largest number of updates (>= 0).
  int max_iterations = 100;
  /// pg_minimize: stop when the loss is at most this.
  double loss_tolerance = -std::numeric_limits<double>::infinity();
  /// pg_minimize: stop when the wall time reaches this many seconds (checked after every
  /// update).
  double time_limit = std::numeric_limits<double>::infinity();
  /// pg_minimize: throw OptimizationError (carrying the summary) when the loss, P(x) or the
  /// inverse simulator's result is not finite; otherwise only the summary reports it
  /// (termination loss_not_finite or gradient_not_finite).
  bool throw_on_failure = true;
};

/// What one PG update saw and did.
struct PgStep {
  double loss = 0.0;        ///< L(P(x)) before the update
  double update_norm = 0.0; ///< |x' - x|
};

/// What pg_minimize did.
struct PgSummary : MinimizerSummary {};

namespace detail {

inline void check_pg(const PhysicalGradientProblem& p, const PgOptions& o) {
  if (!p.forward || !p.inverse || !p.loss)
    throw std::invalid_argument("pg: the problem needs forward, inverse and loss callables");
  if (!(o.learning_rate > 0.0) || !std::isfinite(o.learning_rate))
    throw std::invalid_argument(
        message("pg: learning_rate must be positive and finite (got ", o.learning_rate, ")"));
  if (o.max_iterations < 0)
    throw std::invalid_argument(
        message("pg: max_iterations must be >= 0 (got ", o.max_iterations, ")"));
}

// The first half of a PG update: P(x), the loss and its Newton step in y. Returns
// max_iterations ("all finite") or loss_not_finite (the loss or P(x) is NaN or Inf), with the
// message in `what`.
inline Termination pg_loss(const PhysicalGradientProblem& problem, const Eigen::VectorXd& x,
                           PgStep& step, Eigen::VectorXd& y, Eigen::VectorXd& newton,
                           std::string& what) {
  y = problem.forward(x);
  const Eigen::Index bad = first_non_finite(y);
  if (bad >= 0) {
    step.loss = std::numeric_limits<double>::quiet_NaN();
    what = message("pg: P(x) contains ", format_number(y[bad]), " at index ", bad);
    return Termination::loss_not_finite;
  }
  step.loss = problem.loss(y, newton);
  if (!std::isfinite(step.loss)) {
    what = message("pg: loss is ", step.loss, " at the current x");
    return Termination::loss_not_finite;
  }
  require_size(newton.size(), y.size(), "pg", "Newton step in y");
  return Termination::max_iterations;
}

// The second half: x_new = P^-1(y - lr newton; x). Returns max_iterations ("all finite") or
// gradient_not_finite (the inverse simulator's result is NaN or Inf), with the message in `what`.
inline Termination pg_inverse(const PhysicalGradientProblem& problem, const Eigen::VectorXd& x,
                              const Eigen::VectorXd& y, const Eigen::VectorXd& newton,
                              const PgOptions& options, PgStep& step, Eigen::VectorXd& x_new,
                              std::string& what) {
  const Eigen::VectorXd y_target = y - options.learning_rate * newton; // y' = y - lr H^-1 g
  x_new = problem.inverse(y_target, x);                                // x' = P^-1(y')
  require_size(x_new.size(), x.size(), "pg", "inverse simulator's result");
  const Eigen::Index bad = first_non_finite(x_new);
  if (bad >= 0) {
    what = message("pg: inverse simulator's result contains ", format_number(x_new[bad]),
                   " at index ", bad);
    return Termination::gradient_not_finite;
  }
  step.update_norm = (x_new - x).norm();
  return Termination::max_iterations;
}

// The whole PG update of x into x_new (pg_loss, then pg_inverse).
inline Termination pg_update(const PhysicalGradientProblem& problem, const Eigen::VectorXd& x,
                             const PgOptions& options, PgStep& step, Eigen::VectorXd& x_new,
                             std::string& what) {
  Eigen::VectorXd y, newton;
  const Termination t = pg_loss(problem, x, step, y, newton, what);
  return t != Termination::max_iterations
             ? t
             : pg_inverse(problem, x, y, newton, options, step, x_new, what);
}

} // namespace detail

/// The PG target x' = P^-1(P(x) - lr (d2L/dy2)^-1 dL/dy; x) for the current x. Reports L(P(x))
/// and |x' - x| in `step`. Throws std::invalid_argument on NaN/Inf or mismatched sizes.
inline Eigen::VectorXd physical_update(const PhysicalGradientProblem& problem,
                                       const Eigen::VectorXd& x, const PgOptions& options = {},
                                       PgStep* step = nullptr) {
  detail::check_pg(problem, options);
  detail::require_finite(x, "pg", "x");
  PgStep local;
  Eigen::VectorXd x_new;
  std::string what;
  if (detail::pg_update(problem, x, options, local, x_new, what) != Termination::max_iterations)
    throw std::invalid_argument(what);
  if (step)
    *step = local;
  return x_new;
}

/// Minimises L(P(x)) over x (updated in place) with PG updates, stopping on the loss tolerance
/// (checked before every update), the time limit or max_iterations. When the loss, P(x) or the
/// inverse simulator's result is not finite it stops (loss_not_finite / gradient_not_finite,
/// x left at the last finite iterate) and throws OptimizationError carrying the summary, or
/// only reports it when options.throw_on_failure is off.
inline PgSummary pg_minimize(const PhysicalGradientProblem& problem, Eigen::VectorXd& x,
                             const PgOptions& options = {}) {
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  detail::check_pg(problem, options);
  detail::require_finite(x, "pg", "x");
  PgSummary summary;
  PgStep step;
  Eigen::VectorXd y, newton, x_new;
  std::string what;
  const auto fail = [&](Termination t) {
    summary.termination = t;
    summary.message = detail::message(what, " (after ", summary.iterations, " updates)");
  };
  for (;;) {
    // The loss first: a run that has converged or reached its limits stops without the
    // inverse solve of an update it would not apply.
    const Termination t = detail::pg_loss(problem, x, step, y, newton, what);
    if (summary.iterations == 0)
      summary.initial_loss = step.loss;
    summary.final_loss = step.loss;
    if (t != Termination::max_iterations) {
      fail(t);
      break;
    }
    if (step.loss <= options.loss_tolerance) {
      summary.termination = Termination::loss_tolerance;
      break;
    }
    if (summary.iterations == options.max_iterations) {
      summary.termination = Termination::max_iterations;
      break;
    }
    if (std::chrono::duration<double>(clock::now() - start).count() >= options.time_limit) {
      summary.termination = Termination::time_limit;
      break;
    }
    const Termination u = detail::pg_inverse(problem, x, y, newton, options, step, x_new, what);
    if (u != Termination::max_iterations) {
      fail(u);
      break;
    }
    x = x_new;
    ++summary.iterations;
  }
  summary.seconds = std::chrono::duration<double>(clock::now() - start).count();
  if (summary.failed()) {
    if (options.throw_on_failure)
      throw OptimizationError(summary);
    return summary;
  }
  summary.message = detail::message("pg: ", to_string(summary.termination), " after ",
                                    summary.iterations, " updates, loss ", summary.final_loss);
  return summary;
}

/// The regularized local inverse of a linear simulator P around x: returns x + d with
///   (P^T P + lambda I) d = P^T (y_target - P x),
/// solved by CG with `apply` (y = P x) and `apply_adjoint` (x = P^T y, e.g. the generated
/// adjoint kernel). lambda > 0 damps the directions P shrinks below sqrt(lambda) (the high
/// frequencies a diffusion wipes out), which an exact inverse would amplify without bound.
inline Eigen::VectorXd regularized_inverse(const VectorOperator& apply,
                                           const VectorOperator& apply_adjoint,
                                           const Eigen::VectorXd& y_target,
                                           const Eigen::VectorXd& x, double lambda,
                                           CgOptions cg = {}, CgSummary* summary = nullptr) {
  if (!(lambda > 0.0) || !std::isfinite(lambda))
    throw std::invalid_argument(
        detail::message("regularized inverse: lambda must be positive (got ", lambda, ")"));
  Eigen::VectorXd px = Eigen::VectorXd::Zero(y_target.size());
  apply(x, px);
  const Eigen::VectorXd r = y_target - px;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(x.size());
  apply_adjoint(r, rhs); // P^T r
  Eigen::VectorXd py(y_target.size()), normal(x.size());
  // (P^T P + lambda I) v
  const auto normal_operator = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    py.setZero();
    apply(v, py);
    normal.setZero();
    apply_adjoint(py, normal);
    out = normal + lambda * v;
  };
  if (cg.name == "cg")
    cg.name = "regularized inverse (P^T P + lambda I) d = P^T r";
  Eigen::VectorXd d = Eigen::VectorXd::Zero(x.size());
  const CgSummary s = conjugate_gradient(normal_operator, rhs, d, cg);
  if (summary)
    *summary = s;
  return x + d;
}

} // namespace dpgen
