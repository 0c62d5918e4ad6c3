// Half-inverse gradients (HIG; Schnell, Holl & Thuerey 2022, the PBDL book's chapter
// "Half-Inverse Gradients"): the update  dx = -lr V S^k U^T (dL/dy)  from the SVD
// J = U S V^T of the Jacobian of a batch's outputs y w.r.t. the parameters x, with the
// singular values raised to k = -1/2 and the small ones truncated. k = -1 is the
// (pseudo-inverse) Gauss-Newton step, k = 1 plain gradient descent (J^T dL/dy).
#pragma once

#include "dpgen/error.hpp"

#include <Eigen/Core>
#include <Eigen/SVD>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace dpgen {

/// One batch at parameters x: returns the loss L(y(x)), writes dL/dy (size m, all outputs of
/// the batch stacked) into `loss_grad` and the m-by-n Jacobian dy/dx into `jacobian`.
using LossOutputsJacobian = std::function<double(const Eigen::VectorXd& x,
                                                 Eigen::VectorXd& loss_grad,
                                                 Eigen::MatrixXd& jacobian)>;

/// Settings of the HIG update and of hig_minimize.
struct HigOptions {
  /// lr in x <- x - lr V S^k U^T dL/dy (> 0). The book uses 1.
  double learning_rate = 1.0;
  /// k, the power of the kept singular values: -1/2 for HIG, -1 Gauss-Newton, 1 GD (finite).
  double exponent = -0.5;
  /// Singular values at or below truncation * (largest singular value) are dropped, as
  /// numpy's pinv rcond does (0 <= truncation < 1; the book's oscillator example uses 1e-10).
  double truncation = 1e-10;
  /// hig_minimize: largest number of updates (>= 0).
  int max_iterations = 100;
  /// hig_minimize: stop when the loss is at most this.
  double loss_tolerance = -std::numeric_limits<double>::infinity();
  /// hig_minimize: stop when |dx| is at most this.
  double step_tolerance = 0.0;
};

/// What one HIG update saw and did.
struct HigStep {
  double loss = 0.0;                    ///< L at x before the update
  double update_norm = 0.0;             ///< |dx|
  Eigen::Index singular_values = 0;     ///< min(m, n)
  Eigen::Index kept = 0;                ///< singular values above the truncation threshold
  double largest_singular_value = 0.0;  ///< S_max (0 for a zero Jacobian)
  double smallest_kept_singular_value = 0.0;
};

/// Why hig_minimize stopped.
enum class HigTermination {
  max_iterations, ///< the iteration limit was reached
  loss_tolerance, ///< L <= loss_tolerance
  step_tolerance, ///< |dx| <= step_tolerance
  no_direction,   ///< every singular value was truncated (a zero Jacobian): dx = 0
};

/// The enumerator's name, for messages and logs.
inline const char* to_string(HigTermination termination) {
  switch (termination) {
  case HigTermination::max_iterations:
    return "max_iterations";
  case HigTermination::loss_tolerance:
    return "loss_tolerance";
  case HigTermination::step_tolerance:
    return "step_tolerance";
  case HigTermination::no_direction:
    return "no_direction";
  }
  return "unknown";
}

/// What hig_minimize did.
struct HigSummary {
  int iterations = 0; ///< updates applied
  double initial_loss = 0.0;
  double final_loss = 0.0; ///< L at the returned x
  HigStep last_step;       ///< the last update's singular-value statistics
  HigTermination termination = HigTermination::max_iterations;
  std::string message; ///< one line saying why it stopped
};

namespace detail {

inline void check_hig_options(const HigOptions& o) {
  if (!(o.learning_rate > 0.0) || !std::isfinite(o.learning_rate))
    throw std::invalid_argument(
        message("hig: learning_rate must be positive and finite (got ", o.learning_rate, ")"));
  if (!std::isfinite(o.exponent))
    throw std::invalid_argument(message("hig: exponent must be finite (got ", o.exponent, ")"));
  if (!(o.truncation >= 0.0 && o.truncation < 1.0))
    throw std::invalid_argument(
        message("hig: truncation must be in [0, 1) (got ", o.truncation, ")"));
  if (o.max_iterations < 0)
    throw std::invalid_argument(
        message("hig: max_iterations must be >= 0 (got ", o.max_iterations, ")"));
}

} // namespace detail

/// The HIG update dx = -lr V S^k U^T g for the m-by-n Jacobian J = U S V^T (thin SVD by
/// Eigen's BDCSVD) and g = dL/dy, over the singular values S_i > truncation * S_max only.
/// Throws std::invalid_argument for mismatched sizes, NaN/Inf entries or bad options.
inline Eigen::VectorXd hig_update(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& loss_grad,
                                  const HigOptions& options = {}, HigStep* step = nullptr) {
  detail::check_hig_options(options);
  if (jacobian.rows() < 1 || jacobian.cols() < 1)
    throw std::invalid_argument(detail::message("hig: the Jacobian is empty (", jacobian.rows(),
                                                " x ", jacobian.cols(), ")"));
  detail::require_size(loss_grad.size(), jacobian.rows(), "hig", "loss gradient dL/dy");
  detail::require_finite(loss_grad, "hig", "loss gradient dL/dy");
  for (Eigen::Index c = 0; c < jacobian.cols(); ++c)
    detail::require_finite(jacobian.col(c), "hig", detail::message("Jacobian column ", c));

  const Eigen::BDCSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues(); // descending
  const double s_max = s.size() > 0 ? s[0] : 0.0;
  const double cutoff = options.truncation * s_max;
  Eigen::Index kept = 0;
  while (kept < s.size() && s[kept] > cutoff && s[kept] > 0.0)
    ++kept;
  // dx = -lr V_k S_k^k U_k^T g: project g on the kept left singular vectors, scale, map back.
  Eigen::VectorXd t = svd.matrixU().leftCols(kept).transpose() * loss_grad;
  for (Eigen::Index i = 0; i < kept; ++i)
    t[i] *= std::pow(s[i], options.exponent);
  Eigen::VectorXd dx = -options.learning_rate * (svd.matrixV().leftCols(kept) * t);
  if (step) {
    step->update_norm = dx.norm();
    step->singular_values = s.size();
    step->kept = kept;
    step->largest_singular_value = s_max;
    step->smallest_kept_singular_value = kept > 0 ? s[kept - 1] : 0.0;
  }
  return dx;
}

/// HIG as a stepwise optimizer: step() evaluates one batch at x and applies its update, so a
/// training loop can feed a different mini-batch each time.
class HalfInverseGradient {
public:
  explicit HalfInverseGradient(HigOptions options = {}) : options_(options) {
    detail::check_hig_options(options_);
  }
  /// Evaluates f at x and updates x in place; returns the loss before the update and the
  /// update's statistics. Throws std::invalid_argument when f's outputs do not fit x.
  HigStep step(Eigen::VectorXd& x, const LossOutputsJacobian& f) {
    Eigen::VectorXd loss_grad;
    Eigen::MatrixXd jac;
    HigStep info;
    info.loss = f(x, loss_grad, jac);
    if (!std::isfinite(info.loss))
      throw std::invalid_argument(detail::message("hig: loss is ", info.loss, " at the current x"));
    detail::require_size(jac.cols(), x.size(), "hig", "Jacobian's column count");
    x += hig_update(jac, loss_grad, options_, &info);
    return info;
  }
  const HigOptions& options() const { return options_; }

private:
  HigOptions options_;
};

/// Minimises L over x (updated in place) with full-batch HIG updates until max_iterations, the
/// loss tolerance, the step tolerance, or a Jacobian without a kept singular value. f is
/// evaluated once per update plus once at the start.
inline HigSummary hig_minimize(const LossOutputsJacobian& f, Eigen::VectorXd& x,
                               const HigOptions& options = {}) {
  detail::check_hig_options(options);
  detail::require_finite(x, "hig", "initial x");
  Eigen::VectorXd g;
  Eigen::MatrixXd jac;
  const auto evaluate = [&]() {
    const double loss = f(x, g, jac);
    if (!std::isfinite(loss))
      throw std::invalid_argument(detail::message("hig: loss is ", loss, " at the current x"));
    detail::require_size(jac.cols(), x.size(), "hig", "Jacobian's column count");
    return loss;
  };
  HigSummary summary;
  double loss = evaluate();
  summary.initial_loss = loss;
  for (;;) {
    summary.final_loss = loss;
    if (loss <= options.loss_tolerance) {
      summary.termination = HigTermination::loss_tolerance;
      break;
    }
    if (summary.iterations == options.max_iterations) {
      summary.termination = HigTermination::max_iterations;
      break;
    }
    HigStep step;
    step.loss = loss;
    const Eigen::VectorXd dx = hig_update(jac, g, options, &step);
    summary.last_step = step;
    if (step.kept == 0) {
      summary.termination = HigTermination::no_direction;
      break;
    }
    x += dx;
    ++summary.iterations;
    loss = evaluate();
    if (step.update_norm <= options.step_tolerance) {
      summary.final_loss = loss;
      summary.termination = HigTermination::step_tolerance;
      break;
    }
  }
  summary.message = detail::message("hig: ", to_string(summary.termination), " after ",
                                    summary.iterations, " updates, loss ", summary.final_loss);
  return summary;
}

} // namespace dpgen
