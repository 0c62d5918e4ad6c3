// Optimizers over one flat parameter vector, all driven by the same loss+gradient callable:
// gradient descent, Adam, and L-BFGS (LBFGS++, stepwise and as a whole minimisation); and,
// from the outputs' Jacobian instead, half-inverse gradients (hig.hpp).
#pragma once

#include "dpgen/error.hpp"
#include "dpgen/hig.hpp"

#include <Eigen/Core>
#include <LBFGS.h>

#include <cmath>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>

namespace dpgen {

/// A loss with its gradient: returns L(x) and overwrites `grad` with dL/dx (sized like x).
using LossGradient = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& grad)>;

/// Thrown when an optimizer cannot make progress (e.g. a failed line search).
class OptimizationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

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

/// Gradient descent with a fixed learning rate: x <- x - lr grad.
class GradientDescent : public Optimizer {
public:
  /// `learning_rate` must be positive.
  explicit GradientDescent(double learning_rate) : learning_rate_(learning_rate) {
    if (!(learning_rate > 0.0) || !std::isfinite(learning_rate))
      throw std::invalid_argument(
          detail::message("gd: learning rate must be positive (got ", learning_rate, ")"));
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

/// What lbfgs_minimize did.
struct LbfgsSummary {
  int iterations = 0;    ///< L-BFGS iterations, as LBFGSSolver counts them
  double loss = 0.0;     ///< L at the returned x
  double grad_norm = 0.; ///< |dL/dx| at the returned x
};

/// Minimises f from x (updated in place) with LBFGSpp::LBFGSSolver<double> and its
/// convergence tests (param.epsilon, epsilon_rel, past/delta, max_iterations), plus one
/// evaluation at the end for the reported gradient norm. LBFGS++'s errors are rethrown as
/// OptimizationError prefixed "lbfgs: ".
inline LbfgsSummary lbfgs_minimize(const LossGradient& f, Eigen::VectorXd& x,
                                   const LBFGSpp::LBFGSParam<double>& param = {}) {
  LBFGSpp::LBFGSSolver<double> solver(param);
  Eigen::VectorXd grad(x.size());
  auto objective = [&](const Eigen::VectorXd& v, Eigen::VectorXd& g) { return f(v, g); };
  LbfgsSummary summary;
  try {
    summary.iterations = solver.minimize(objective, x, summary.loss);
  } catch (const std::exception& e) {
    throw OptimizationError(detail::message("lbfgs: ", e.what()));
  }
  summary.loss = f(x, grad);
  summary.grad_norm = grad.norm();
  return summary;
}

} // namespace dpgen
