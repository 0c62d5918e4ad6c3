// Physical gradients (PG; the PBDL book's chapters "Physical Gradients" and "Scale-Invariant
// Physics Training"): an update of x through an inverse solver instead of the adjoint,
//   y = P(x),  y' = y - lr (d2L/dy2)^-1 dL/dy  (a Newton step of the loss in y),
//   x' = P^-1(y'; x)                           (the inverse simulator, local around x),
// and a regularized local inverse for linear P with a kernel and its adjoint:
//   x' = x + argmin_d |P d - (y' - P x)|^2 + lambda |d|^2,  by CG on (P^T P + lambda I) d = P^T r.
#pragma once

#include "dpgen/cg.hpp"
#include "dpgen/error.hpp"

#include <Eigen/Core>

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
  std::function<Eigen::VectorXd(const Eigen::VectorXd& y_target, const Eigen::VectorXd& x)>
      inverse;
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
};

/// What one PG update saw and did.
struct PgStep {
  double loss = 0.0;        ///< L(P(x)) before the update
  double update_norm = 0.0; ///< |x' - x|
};

/// Why pg_minimize stopped.
enum class PgTermination {
  max_iterations, ///< the iteration limit was reached
  loss_tolerance, ///< L <= loss_tolerance
};

/// What pg_minimize did.
struct PgSummary {
  int iterations = 0;
  double initial_loss = 0.0;
  double final_loss = 0.0; ///< L(P(x)) at the returned x
  PgTermination termination = PgTermination::max_iterations;
  std::string message;
};

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

} // namespace detail

/// The PG target x' = P^-1(P(x) - lr (d2L/dy2)^-1 dL/dy; x) for the current x. Reports L(P(x))
/// and |x' - x| in `step`. Throws std::invalid_argument on NaN/Inf or mismatched sizes.
inline Eigen::VectorXd physical_update(const PhysicalGradientProblem& problem,
                                       const Eigen::VectorXd& x, const PgOptions& options = {},
                                       PgStep* step = nullptr) {
  detail::check_pg(problem, options);
  detail::require_finite(x, "pg", "x");
  const Eigen::VectorXd y = problem.forward(x);
  detail::require_finite(y, "pg", "P(x)");
  Eigen::VectorXd newton;
  const double loss = problem.loss(y, newton);
  if (!std::isfinite(loss))
    throw std::invalid_argument(detail::message("pg: loss is ", loss, " at the current x"));
  detail::require_size(newton.size(), y.size(), "pg", "Newton step in y");
  const Eigen::VectorXd y_target = y - options.learning_rate * newton; // y' = y - lr H^-1 g
  Eigen::VectorXd x_new = problem.inverse(y_target, x);                  // x' = P^-1(y')
  detail::require_size(x_new.size(), x.size(), "pg", "inverse simulator's result");
  detail::require_finite(x_new, "pg", "inverse simulator's result");
  if (step) {
    step->loss = loss;
    step->update_norm = (x_new - x).norm();
  }
  return x_new;
}

/// Minimises L(P(x)) over x (updated in place) with PG updates.
inline PgSummary pg_minimize(const PhysicalGradientProblem& problem, Eigen::VectorXd& x,
                             const PgOptions& options = {}) {
  detail::check_pg(problem, options);
  PgSummary summary;
  PgStep step;
  for (;;) {
    const Eigen::VectorXd x_new = physical_update(problem, x, options, &step);
    if (summary.iterations == 0)
      summary.initial_loss = step.loss;
    summary.final_loss = step.loss;
    if (step.loss <= options.loss_tolerance) {
      summary.termination = PgTermination::loss_tolerance;
      break;
    }
    if (summary.iterations == options.max_iterations) {
      summary.termination = PgTermination::max_iterations;
      break;
    }
    x = x_new;
    ++summary.iterations;
  }
  summary.message = detail::message(
      "pg: ", summary.termination == PgTermination::loss_tolerance ? "loss_tolerance" : "max_iterations",
      " after ", summary.iterations, " updates, loss ", summary.final_loss);
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
