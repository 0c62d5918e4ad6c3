// Optimizers over one flat parameter vector: gradient descent, Adam and L-BFGS (LBFGS++,
// stepwise and as a whole minimisation) driven by one loss+gradient callable, and half-inverse
// gradients (HIG) driven by a residual and its Jacobian.
#pragma once

#include "dpgen/error.hpp"
#include "dpgen/termination.hpp"

#include <Eigen/Core>
#include <Eigen/SVD>
#include <LBFGS.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

// Eigen's BDCSVD (hig_update's and hig_minimize's default SVD) costs each file that calls them
// about 30 s of compile time with g++ -O3. A program with several such files can compile it
// once: define DPGEN_EXTERN_BDCSVD in all of them and put the explicit instantiation
// `template class Eigen::BDCSVD<Eigen::MatrixXd>;` in one file (dpgen's own tests and examples
// link runtime/src/bdcsvd.cpp, target dpgen_bdcsvd).
#ifdef DPGEN_EXTERN_BDCSVD
extern template class Eigen::BDCSVD<Eigen::MatrixXd>;
#endif

namespace dpgen {

/// A loss with its gradient: returns L(x) and overwrites `grad` with dL/dx (sized like x).
using LossGradient = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& grad)>;

/// One update rule. The training loop (train.hpp) calls step() once per iteration.
class Optimizer {
public:
  virtual ~Optimizer() = default;
  /// Performs one update. On entry x, loss and grad describe the current iterate (loss = f(x),
  /// grad = dL/dx); on return they describe the new iterate, where f has been evaluated.
  /// Returns the number of evaluations of f it made.
  virtual int step(Eigen::VectorXd& x, double& loss, Eigen::VectorXd& grad,
                   const LossGradient& f) = 0;
  /// Forgets internal state (moments, curvature pairs), as if no step had been taken.
  virtual void reset() {}
  /// A short name for messages and logs ("gd", "adam", "lbfgs").
  virtual std::string name() const = 0;
};

/// Gradient descent's settings.
struct GradientDescentOptions {
  double learning_rate = 1e-2; ///< lr in x <- x - lr grad (must be positive)
};

/// Gradient descent with a fixed learning rate: x <- x - lr grad.
class GradientDescent : public Optimizer {
public:
  explicit GradientDescent(const GradientDescentOptions& options = {})
      : learning_rate_(options.learning_rate) {
    if (!(learning_rate_ > 0.0) || !std::isfinite(learning_rate_))
      throw std::invalid_argument(
          detail::message("gd: learning rate must be positive (got ", learning_rate_, ")"));
  }
  int step(Eigen::VectorXd& x, double& loss, Eigen::VectorXd& grad,
           const LossGradient& f) override {
    x -= learning_rate_ * grad; // x_{k+1} = x_k - lr g_k
    loss = f(x, grad);
    return 1;
  }
  std::string name() const override { return "gd"; }

private:
  double learning_rate_;
};

/// Adam's hyper-parameters; the defaults are those of Kingma & Ba (2015).
struct AdamOptions {
  double learning_rate = 1e-3;
  double beta1 = 0.9;
  double beta2 = 0.999;
  double epsilon = 1e-8;
};

/// Adam with bias correction (Kingma & Ba, Algorithm 1).
class Adam : public Optimizer {
public:
  explicit Adam(AdamOptions options = {}) : options_(options) {
    if (!(options.learning_rate > 0.0) || !(options.beta1 >= 0.0 && options.beta1 < 1.0) ||
        !(options.beta2 >= 0.0 && options.beta2 < 1.0) || !(options.epsilon > 0.0))
      throw std::invalid_argument(detail::message(
          "adam: need learning_rate > 0, 0 <= beta1, beta2 < 1 and epsilon > 0 (got ",
          options.learning_rate, ", ", options.beta1, ", ", options.beta2, ", ", options.epsilon,
          ")"));
  }
  int step(Eigen::VectorXd& x, double& loss, Eigen::VectorXd& grad,
           const LossGradient& f) override {
    if (m_.size() != x.size())
      reset_to(x.size());
    ++t_;
    const AdamOptions& o = options_;
    m_ = o.beta1 * m_ + (1.0 - o.beta1) * grad;                         // m_t = b1 m + (1-b1) g
    v_ = o.beta2 * v_ + (1.0 - o.beta2) * grad.cwiseAbs2();             // v_t = b2 v + (1-b2) g^2
    const double c1 = 1.0 - std::pow(o.beta1, static_cast<double>(t_)); // m^_t = m_t / c1
    const double c2 = 1.0 - std::pow(o.beta2, static_cast<double>(t_)); // v^_t = v_t / c2
    x.array() -= o.learning_rate * (m_.array() / c1) / ((v_.array() / c2).sqrt() + o.epsilon);
    loss = f(x, grad);
    return 1;
  }
  void reset() override { reset_to(0); }
  std::string name() const override { return "adam"; }

private:
  void reset_to(Eigen::Index n) {
    m_.setZero(n);
    v_.setZero(n);
    t_ = 0;
  }
  AdamOptions options_;
  Eigen::VectorXd m_, v_;
  long long t_ = 0;
};

/// L-BFGS, one iteration per step(): the two-loop update of LBFGS++'s BFGSMat and its
/// backtracking line search, exactly the iteration LBFGSpp::LBFGSSolver::minimize performs
/// (same evaluations, same iterates), so the training loop can log and stop between
/// iterations. Convergence tests are the training loop's; LBFGSParam's epsilon, past, delta
/// and max_iterations are not used here (lbfgs_minimize uses them).
class Lbfgs : public Optimizer {
public:
  explicit Lbfgs(const LBFGSpp::LBFGSParam<double>& param = {}) : param_(param) {
    param_.check_param();
  }
  int step(Eigen::VectorXd& x, double& loss, Eigen::VectorXd& grad,
           const LossGradient& f) override {
    const Eigen::Index n = x.size();
    if (grad.size() != n)
      throw std::invalid_argument(
          detail::message("lbfgs: gradient has size ", grad.size(), ", expected ", n));
    if (grad.norm() == 0.0)
      return 0; // already stationary: no direction to search along
    if (iteration_ == 0 || drt_.size() != n) {
      bfgs_.reset(static_cast<int>(n), param_.m);
      iteration_ = 0;
      drt_ = -grad;              // d_0 = -g_0
      step_ = 1.0 / drt_.norm(); // first trial step: unit length
    } else {
      step_ = 1.0; // d_k = -H_k g_k was prepared by the previous step
    }
    xp_ = x;
    gradp_ = grad;
    int evaluations = 0;
    auto counted = [&](const Eigen::VectorXd& v, Eigen::VectorXd& g) {
      ++evaluations;
      return f(v, g);
    };
    try {
      LBFGSpp::LineSearchBacktracking<double>::LineSearch(counted, loss, x, grad, step_, drt_, xp_,
                                                          param_);
    } catch (const std::exception& e) {
      throw OptimizationError(detail::message("lbfgs: line search failed in iteration ",
                                              iteration_ + 1, ": ", e.what()));
    }
    ++iteration_;
    bfgs_.add_correction(x - xp_, grad - gradp_); // s_k = x_{k+1} - x_k, y_k = g_{k+1} - g_k
    bfgs_.apply_Hv(grad, -1.0, drt_);             // d_{k+1} = -H_{k+1} g_{k+1}
    return evaluations;
  }
  void reset() override { iteration_ = 0; }
  std::string name() const override { return "lbfgs"; }

private:
  LBFGSpp::LBFGSParam<double> param_;
  LBFGSpp::BFGSMat<double> bfgs_;
  Eigen::VectorXd xp_, gradp_, drt_;
  double step_ = 1.0;
  int iteration_ = 0;
};

/// Settings of lbfgs_minimize: LBFGS++'s parameters (epsilon, epsilon_rel, past, delta,
/// max_iterations, the line search's) plus what to do on failure.
struct LbfgsOptions : LBFGSpp::LBFGSParam<double> {
  /// Throw OptimizationError (carrying the summary) when the run fails (NaN/Inf loss or
  /// gradient, failed line search); otherwise only the summary reports it.
  bool throw_on_failure = true;
};

/// What lbfgs_minimize did.
/// When L-BFGS stops on a failure (line_search_failed, a non-finite loss or gradient), LBFGS++
/// does not say after how many iterations: `iterations` and `final_grad_norm` stay 0 then, and
/// `evaluations` (and the message) say when.
struct LbfgsSummary : MinimizerSummary {
  double final_grad_norm = 0.0; ///< |dL/dx| at the returned x (0 after a failure)
  int evaluations = 0;          ///< evaluations of f in all
};

namespace detail {
// Thrown from inside LBFGSSolver::minimize to stop it on a non-finite loss or gradient.
struct LbfgsStop {
  Termination termination;
  std::string message;
};
} // namespace detail

/// Minimises f from x (updated in place) with LBFGSpp::LBFGSSolver<double> and its
/// convergence tests (epsilon or epsilon_rel: gradient_tolerance; past/delta: loss_decrease;
/// max_iterations), plus one evaluation at the end for the reported gradient norm. A NaN or Inf
/// loss at the start, or a NaN or Inf gradient anywhere, stops the run (loss_not_finite,
/// gradient_not_finite); LBFGS++'s line-search errors stop it as line_search_failed ("lbfgs: "
/// and LBFGS++'s message). Failures throw OptimizationError carrying the summary unless
/// options.throw_on_failure is off; errors of f propagate unchanged. `iterations` counts line
/// searches (0 when x0 already meets the gradient tolerance).
inline LbfgsSummary lbfgs_minimize(const LossGradient& f, Eigen::VectorXd& x,
                                   const LbfgsOptions& options = {}) {
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  LBFGSpp::LBFGSSolver<double> solver(options);
  Eigen::VectorXd grad(x.size());
  LbfgsSummary summary;
  std::exception_ptr error_of_f; // f's own errors pass through LBFGS++ unchanged
  auto objective = [&](const Eigen::VectorXd& v, Eigen::VectorXd& g) {
    double fx = 0.0;
    try {
      fx = f(v, g);
    } catch (...) {
      error_of_f = std::current_exception();
      throw;
    }
    ++summary.evaluations;
    summary.final_loss = fx; // x holds the last evaluated point, also when a line search fails
    if (summary.evaluations == 1) {
      summary.initial_loss = fx;
      if (!std::isfinite(fx))
        throw detail::LbfgsStop{Termination::loss_not_finite,
                                detail::message("lbfgs: loss is ", std::isnan(fx) ? "NaN" : "Inf",
                                                " at the initial point")};
    }
    const Eigen::Index bad = detail::first_non_finite(g);
    if (bad >= 0)
      throw detail::LbfgsStop{Termination::gradient_not_finite,
                              detail::message("lbfgs: gradient is ",
                                              std::isnan(g[bad]) ? "NaN" : "Inf", " (index ", bad,
                                              ") at evaluation ", summary.evaluations)};
    return fx;
  };
  bool stopped = false;
  try {
    double fx = 0.0;
    const int k = solver.minimize(objective, x, fx);
    summary.iterations = summary.evaluations == 1 ? 0 : k;
  } catch (const detail::LbfgsStop& stop) {
    summary.termination = stop.termination;
    summary.message = stop.message;
    stopped = true;
  } catch (const std::exception& e) {
    if (error_of_f)
      std::rethrow_exception(error_of_f);
    summary.termination = Termination::line_search_failed;
    summary.message = detail::message("lbfgs: ", e.what());
    stopped = true;
  }
  if (stopped) {
    summary.seconds = std::chrono::duration<double>(clock::now() - start).count();
    if (options.throw_on_failure)
      throw OptimizationError(summary);
    return summary;
  }
  summary.final_loss = f(x, grad);
  ++summary.evaluations;
  summary.final_grad_norm = grad.norm();
  if (summary.final_grad_norm <= options.epsilon ||
      summary.final_grad_norm <= options.epsilon_rel * x.norm())
    summary.termination = Termination::gradient_tolerance;
  else if (options.max_iterations != 0 && summary.iterations >= options.max_iterations)
    summary.termination = Termination::max_iterations;
  else
    summary.termination = Termination::loss_decrease;
  summary.seconds = std::chrono::duration<double>(clock::now() - start).count();
  summary.message =
      detail::message("lbfgs: ", to_string(summary.termination), " after ", summary.iterations,
                      " iterations (", describe(summary.termination), "), loss ",
                      summary.final_loss, ", gradient norm ", summary.final_grad_norm);
  return summary;
}

/// A residual with its Jacobian: returns r(x) (size m) and overwrites `jac` with the m-by-n
/// Jacobian dr/dx (n = x.size()); jacobian.hpp assembles it from tangents or adjoints. The loss
/// is L(x) = 1/2 |r(x)|^2, with gradient J^T r.
using ResidualJacobian =
    std::function<Eigen::VectorXd(const Eigen::VectorXd& x, Eigen::MatrixXd& jac)>;

/// Settings of the half-inverse-gradient update and of hig_minimize.
struct HigOptions {
  /// eta in dx = -eta V Sigma^kappa U^T r (must be positive).
  double learning_rate = 1.0;
  /// kappa: -1/2 is the half-inverse gradient, -1 the Gauss-Newton step (pseudo-inverse),
  /// +1 gradient descent (V Sigma U^T r = J^T r). Any finite value.
  double exponent = -0.5;
  /// Singular values sigma_i <= truncation * sigma_max are dropped (their directions take no
  /// step); zero singular values always are. In [0, 1).
  double truncation = 1e-6;
  /// Largest number of updates hig_minimize performs (>= 0).
  int max_iterations = 100;
  /// hig_minimize stops when L = 1/2 |r|^2 is at most this.
  double loss_tolerance = 0.0;
  /// hig_minimize stops when an update has norm at most this (a zero Jacobian or residual
  /// gives a zero update).
  double step_tolerance = 0.0;
  /// hig_minimize stops when its wall time reaches this many seconds (checked after every
  /// update).
  double time_limit = std::numeric_limits<double>::infinity();
  /// hig_minimize: throw OptimizationError (carrying the summary) when r or J is not finite;
  /// otherwise only the summary reports it (termination loss_not_finite or
  /// gradient_not_finite).
  bool throw_on_failure = true;
};

/// One half-inverse-gradient update, from an SVD J = U Sigma V^T.
struct HigUpdate {
  Eigen::VectorXd step;            ///< dx = -eta V Sigma^kappa U^T r over the kept sigma_i
  Eigen::VectorXd singular_values; ///< all min(m, n) of them, decreasing
  Eigen::Index rank = 0;           ///< how many singular values were kept
};

namespace detail {

inline void check_hig_options(const HigOptions& o) {
  if (!(o.learning_rate > 0.0) || !std::isfinite(o.learning_rate) || !std::isfinite(o.exponent) ||
      !(o.truncation >= 0.0 && o.truncation < 1.0))
    throw std::invalid_argument(
        message("hig: need learning_rate > 0, a finite exponent and 0 <= truncation < 1 (got ",
                o.learning_rate, ", ", o.exponent, ", ", o.truncation, ")"));
  if (o.max_iterations < 0)
    throw std::invalid_argument(
        message("hig: max_iterations must be >= 0 (got ", o.max_iterations, ")"));
}

// Checks r and J for NaN or Inf: returns max_iterations (meaning "all finite") or the failure
// (loss_not_finite for r, gradient_not_finite for J) with its message in `what`; `when` ends the
// message (" in iteration 7", or empty).
inline Termination check_finite_hig(const Eigen::VectorXd& r, const Eigen::MatrixXd& jac,
                                    const std::string& when, std::string& what) {
  const Eigen::Index i = first_non_finite(r);
  if (i >= 0) {
    what = message("hig: residual is ", std::isnan(r[i]) ? "NaN" : "Inf", " at index ", i, when);
    return Termination::loss_not_finite;
  }
  const Eigen::Map<const Eigen::VectorXd> entries(jac.data(), jac.size());
  const Eigen::Index k = first_non_finite(entries);
  if (k >= 0) {
    what = message("hig: Jacobian is ", std::isnan(entries[k]) ? "NaN" : "Inf", " at (",
                   k % jac.rows(), ", ", k / jac.rows(), ")", when);
    return Termination::gradient_not_finite;
  }
  return Termination::max_iterations;
}

// Throws OptimizationError when r or J holds a NaN or Inf, naming which and where.
inline void require_finite_hig(const Eigen::VectorXd& r, const Eigen::MatrixXd& jac,
                               const std::string& when) {
  std::string what;
  if (check_finite_hig(r, jac, when, what) != Termination::max_iterations)
    throw OptimizationError(what);
}

} // namespace detail

/// The half-inverse-gradient update for residual r and Jacobian J = dr/dx (m-by-n):
/// with J = U Sigma V^T (Eigen's BDCSVD, thin U and V),
///   dx = -eta V Sigma^kappa U^T r,
/// summed over the singular values above truncation * sigma_max. kappa = -1/2 scales every
/// direction halfway between gradient descent (kappa = 1: J^T r) and Gauss-Newton
/// (kappa = -1: J^+ r). For a loss other than 1/2 |r|^2 of outputs y with J = dy/dx, pass
/// r = dL/dy (the book's form; e.g. 2 (y - y*) / batch for a mean squared error).
/// Throws std::invalid_argument on bad options or sizes and OptimizationError when r or J is
/// not finite or the SVD fails.
/// Svd is the decomposition (Eigen::JacobiSVD<Eigen::MatrixXd> is more accurate for small,
/// ill-conditioned Jacobians). It is a template parameter so that only the files that call
/// hig_update compile Eigen's SVD: as an inline function it cost every file that includes this
/// header (train.hpp does) about 15 s of compile time.
template <class Svd = Eigen::BDCSVD<Eigen::MatrixXd>>
HigUpdate hig_update(const Eigen::MatrixXd& jac, const Eigen::VectorXd& r,
                     const HigOptions& options = {}) {
  detail::check_hig_options(options);
  detail::require_size(r.size(), jac.rows(), "hig", "residual");
  detail::require_finite_hig(r, jac, "");
  HigUpdate update;
  if (jac.size() == 0) {
    update.step.setZero(jac.cols());
    return update;
  }
  const Svd svd(jac, Eigen::ComputeThinU | Eigen::ComputeThinV);
  if (svd.info() != Eigen::Success)
    throw OptimizationError("hig: the SVD of the Jacobian failed");
  update.singular_values = svd.singularValues();
  const Eigen::VectorXd& sigma = update.singular_values;
  const double cutoff = options.truncation * sigma[0]; // sigma is sorted, sigma_0 = sigma_max
  Eigen::VectorXd c = svd.matrixU().transpose() * r;   // c = U^T r, one entry per direction
  for (Eigen::Index i = 0; i < c.size(); ++i) {
    if (sigma[i] > cutoff && sigma[i] > 0.0) {
      c[i] *= std::pow(sigma[i], options.exponent); // c_i <- sigma_i^kappa c_i
      ++update.rank;
    } else {
      c[i] = 0.0; // truncated direction: no step along v_i
    }
  }
  update.step = -options.learning_rate * (svd.matrixV() * c); // dx = -eta V c
  return update;
}

/// What hig_minimize did.
struct HigSummary : MinimizerSummary {
  Eigen::Index rank = 0; ///< singular values kept in the last update
};

/// Minimises L = 1/2 |r|^2 from x (updated in place) with half-inverse-gradient updates
/// x <- x + hig_update(J(x), r(x)).step, one evaluation of f per iteration, stopping on the
/// loss tolerance (checked before every update, so a start that meets it takes none), the
/// step tolerance, the time limit, or max_iterations. As soon as r or J is not finite
/// (termination loss_not_finite or gradient_not_finite; x then holds the offending iterate) it
/// throws OptimizationError ("hig: residual is NaN at index 3 in iteration 7") carrying the
/// summary, or returns it when options.throw_on_failure is off. Throws std::invalid_argument on
/// bad options or when f returns the wrong sizes. Svd: as for hig_update.
template <class Svd = Eigen::BDCSVD<Eigen::MatrixXd>>
HigSummary hig_minimize(const ResidualJacobian& f, Eigen::VectorXd& x,
                        const HigOptions& options = {}) {
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  detail::check_hig_options(options);
  detail::require_finite(x, "hig", "initial parameter vector");
  Eigen::VectorXd r;
  Eigen::MatrixXd jac;
  HigSummary summary;
  // Evaluates r and J at x, checks their sizes and values, and sets the loss L = 1/2 |r|^2;
  // returns false (with the summary's termination and message set) when r or J is not finite.
  auto evaluate = [&](int iteration) {
    r = f(x, jac);
    if (jac.rows() != r.size() || jac.cols() != x.size())
      throw std::invalid_argument(detail::message("hig: Jacobian is ", jac.rows(), "x", jac.cols(),
                                                  ", expected ", r.size(), "x", x.size()));
    summary.final_loss = 0.5 * r.squaredNorm();
    const Termination t = detail::check_finite_hig(
        r, jac, detail::message(" in iteration ", iteration), summary.message);
    if (t == Termination::max_iterations)
      return true;
    summary.termination = t;
    return false;
  };
  bool finite = evaluate(0);
  summary.initial_loss = summary.final_loss;
  while (finite) {
    if (summary.final_loss <= options.loss_tolerance) {
      summary.termination = Termination::loss_tolerance;
      break;
    }
    if (summary.iterations >= options.max_iterations) {
      summary.termination = Termination::max_iterations;
      break;
    }
    const HigUpdate update = hig_update<Svd>(jac, r, options);
    x += update.step;
    summary.rank = update.rank;
    ++summary.iterations;
    finite = evaluate(summary.iterations);
    if (!finite)
      break;
    if (update.step.norm() <= options.step_tolerance) {
      summary.termination = Termination::step_tolerance;
      break;
    }
    if (std::chrono::duration<double>(clock::now() - start).count() >= options.time_limit) {
      summary.termination = Termination::time_limit;
      break;
    }
  }
  summary.seconds = std::chrono::duration<double>(clock::now() - start).count();
  switch (summary.termination) {
  case Termination::max_iterations:
    summary.message = detail::message("hig: stopped after ", summary.iterations,
                                      " iterations (the limit), loss ", summary.final_loss);
    break;
  case Termination::loss_tolerance:
    summary.message =
        detail::message("hig: converged after ", summary.iterations, " iterations, loss ",
                        summary.final_loss, " <= tolerance ", options.loss_tolerance);
    break;
  case Termination::step_tolerance:
    summary.message = detail::message("hig: stopped after ", summary.iterations,
                                      " iterations, update norm <= tolerance ",
                                      options.step_tolerance, ", loss ", summary.final_loss);
    break;
  case Termination::time_limit:
    summary.message =
        detail::message("hig: stopped after ", summary.iterations, " iterations (time limit ",
                        options.time_limit, " s reached), loss ", summary.final_loss);
    break;
  default: // loss_not_finite, gradient_not_finite: the message is set
    if (options.throw_on_failure)
      throw OptimizationError(summary);
    break;
  }
  return summary;
}

} // namespace dpgen
