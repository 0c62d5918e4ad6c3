// Tests of dpgen/train.hpp: progress rows (the observer callback), stopping rules and their
// termination reasons, each optimizer through the loop, and the NaN/Inf errors that name the
// iteration. (The examples' CSV log that hooks into the observer: csv_log_test.cpp.)
#include "dpgen/train.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace {

using Eigen::VectorXd;

// f(x) = 1/2 sum_i (i + 1) (x_i - 1)^2: minimum 0 at x = 1.
double bowl(const VectorXd& x, VectorXd& grad) {
  const VectorXd w = VectorXd::LinSpaced(x.size(), 1.0, double(x.size()));
  grad = w.cwiseProduct(x - VectorXd::Ones(x.size()));
  return 0.5 * w.dot((x - VectorXd::Ones(x.size())).cwiseAbs2());
}

} // namespace

TEST_CASE("training: the observer is called once per iteration, in order, with its row") {
  std::vector<dpgen::TrainProgress> rows;
  std::vector<VectorXd> iterates; // x as the observer sees it: the row's iterate
  VectorXd x = VectorXd::Zero(4);
  dpgen::TrainOptions options;
  options.max_iterations = 5;
  options.callback = [&](const dpgen::TrainProgress& p) {
    rows.push_back(p);
    iterates.push_back(x);
  };
  dpgen::GradientDescent gd({0.1});
  VectorXd g0;
  const double loss0 = bowl(x, g0);
  const dpgen::TrainSummary summary = dpgen::train(bowl, gd, x, options);

  CHECK(summary.iterations == 5);
  CHECK(summary.termination == dpgen::Termination::max_iterations);
  CHECK_FALSE(summary.converged());
  CHECK_FALSE(summary.failed());
  CHECK(summary.evaluations == 6);
  CHECK(summary.initial_loss == loss0);
  REQUIRE(rows.size() == 6);
  CHECK(rows[0].loss == loss0); // row 0: the state before the first update
  CHECK(rows[0].grad_norm == g0.norm());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(rows[i].iteration == static_cast<int>(i));
    CHECK(rows[i].seconds >= 0.0);
    if (i > 0)
      CHECK(rows[i].loss < rows[i - 1].loss); // lr 0.1 < 2 / 4: gradient descent decreases
  }
  CHECK(summary.final_loss == rows.back().loss);
  double seconds = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    VectorXd g;
    CHECK(rows[i].loss == bowl(iterates[i], g)); // each row reports its own iterate
    CHECK(rows[i].grad_norm == g.norm());
    CHECK(rows[i].evaluations == 1);
    seconds += rows[i].seconds;
  }
  CHECK(summary.seconds == seconds);

  // Stopping early: the observer still sees every row up to and including the last one.
  rows.clear();
  iterates.clear();
  options.max_iterations = 1000;
  options.loss_tolerance = 0.5 * loss0;
  x.setZero();
  const dpgen::TrainSummary early = dpgen::train(bowl, gd, x, options);
  CHECK(early.termination == dpgen::Termination::loss_tolerance);
  CHECK(rows.size() == static_cast<std::size_t>(early.iterations) + 1);
  CHECK(rows.back().loss == early.final_loss);
}

TEST_CASE("training stops on the gradient or the loss tolerance") {
  dpgen::TrainOptions options;
  options.max_iterations = 1000;
  options.gradient_tolerance = 1e-8;
  dpgen::Lbfgs lbfgs;
  VectorXd x = VectorXd::Zero(6);
  const dpgen::TrainSummary by_gradient = dpgen::train(bowl, lbfgs, x, options);
  CHECK(by_gradient.termination == dpgen::Termination::gradient_tolerance);
  CHECK(by_gradient.converged());
  CHECK(by_gradient.final_grad_norm <= 1e-8);
  CHECK(by_gradient.iterations < 100);
  CHECK((x - VectorXd::Ones(6)).norm() < 1e-8);
  CHECK(by_gradient.message.find("training (lbfgs): converged after ") == 0);

  dpgen::TrainOptions by_loss_options;
  by_loss_options.max_iterations = 1000;
  by_loss_options.loss_tolerance = 1e-3;
  dpgen::Adam adam(dpgen::AdamOptions{0.05, 0.9, 0.999, 1e-8});
  VectorXd y = VectorXd::Zero(6);
  const dpgen::TrainSummary by_loss = dpgen::train(bowl, adam, y, by_loss_options);
  CHECK(by_loss.termination == dpgen::Termination::loss_tolerance);
  CHECK(by_loss.message.find("training (adam): converged after ") == 0);
  CHECK(by_loss.final_loss <= 1e-3);
  CHECK(by_loss.iterations < 1000);
  VectorXd g;
  CHECK(bowl(y, g) == by_loss.final_loss); // x is left at the reported iterate

  // Already converged: no update at all.
  VectorXd at_minimum = VectorXd::Ones(3);
  dpgen::GradientDescent gd({0.1});
  CHECK(dpgen::train(bowl, gd, at_minimum, options).iterations == 0);
}

TEST_CASE("training: a custom gradient norm (as distributed runs reduce it over ranks)") {
  // A norm twice the Euclidean one, standing in for a norm summed over other ranks' blocks:
  // it is what the rows report and what the gradient tolerance is checked against.
  dpgen::TrainOptions options;
  options.max_iterations = 5;
  options.norm = [](const VectorXd& g) { return 2.0 * g.norm(); };
  std::vector<double> reported;
  options.callback = [&](const dpgen::TrainProgress& p) { reported.push_back(p.grad_norm); };
  dpgen::GradientDescent gd({0.1});
  VectorXd x = VectorXd::Zero(3), g;
  bowl(x, g);
  const double first = 2.0 * g.norm();
  dpgen::train(bowl, gd, x, options);
  REQUIRE(reported.size() == 6);
  CHECK(reported[0] == first);
  // stops on the custom norm: tolerance between the Euclidean norm and twice it
  options.gradient_tolerance = 0.75 * first;
  VectorXd y = VectorXd::Zero(3);
  reported.clear();
  CHECK(dpgen::train(bowl, gd, y, options).iterations > 0);
  // a norm that is NaN (another rank's gradient is) stops every rank alike
  options.norm = [](const VectorXd&) { return std::numeric_limits<double>::quiet_NaN(); };
  VectorXd z = VectorXd::Zero(3);
  CHECK_THROWS_WITH_AS(dpgen::train(bowl, gd, z, options),
                       "training: gradient norm is NaN at iteration 0", dpgen::TrainingError);
}

TEST_CASE("training: NaN or Inf stops with an error naming the iteration") {
  // Gradient descent evaluates once per iteration: evaluation k + 1 is iteration k.
  int evaluations = 0;
  const dpgen::LossGradient poisoned = [&](const VectorXd& x, VectorXd& grad) {
    const double loss = bowl(x, grad);
    return ++evaluations == 8 ? std::numeric_limits<double>::quiet_NaN() : loss;
  };
  dpgen::TrainOptions options;
  options.max_iterations = 50;
  std::vector<double> observed;
  options.callback = [&](const dpgen::TrainProgress& p) { observed.push_back(p.loss); };
  dpgen::GradientDescent gd({0.1});
  VectorXd x = VectorXd::Zero(3);
  try {
    dpgen::train(poisoned, gd, x, options);
    FAIL("expected a TrainingError");
  } catch (const dpgen::TrainingError& e) {
    CHECK(std::string(e.what()) == "training: loss is NaN at iteration 7");
    CHECK(e.iteration() == 7);
    CHECK(e.summary().termination == dpgen::Termination::loss_not_finite);
    CHECK(e.summary().iterations == 7);
    CHECK(e.summary().failed());
    CHECK(std::isnan(e.summary().final_loss));
  }
  // The observer saw the offending row too (a log ends with it).
  REQUIRE(observed.size() == 8);
  CHECK(std::isnan(observed.back()));
  // A TrainingError is an OptimizationError, like every minimizer's failure.
  evaluations = 0;
  VectorXd x2 = VectorXd::Zero(3);
  CHECK_THROWS_AS(dpgen::train(poisoned, gd, x2, options), dpgen::OptimizationError);

  const dpgen::LossGradient infinite = [](const VectorXd& x, VectorXd& grad) {
    bowl(x, grad);
    return std::numeric_limits<double>::infinity();
  };
  VectorXd y = VectorXd::Zero(3);
  CHECK_THROWS_WITH_AS(dpgen::train(infinite, gd, y), "training: loss is Inf at iteration 0",
                       dpgen::TrainingError);

  int calls = 0;
  const dpgen::LossGradient bad_gradient = [&](const VectorXd& x, VectorXd& grad) {
    const double loss = bowl(x, grad);
    if (++calls == 3)
      grad[1] = std::numeric_limits<double>::quiet_NaN();
    return loss;
  };
  VectorXd z = VectorXd::Zero(3);
  CHECK_THROWS_WITH_AS(dpgen::train(bad_gradient, gd, z),
                       "training: gradient is NaN at iteration 2 (index 1)", dpgen::TrainingError);
}

TEST_CASE("training: termination reasons in the summary (throw_on_failure off)") {
  dpgen::GradientDescent gd({0.1});
  dpgen::TrainOptions options;
  options.throw_on_failure = false;

  options.max_iterations = 3;
  VectorXd x = VectorXd::Zero(3);
  const dpgen::TrainSummary limit = dpgen::train(bowl, gd, x, options);
  CHECK(limit.termination == dpgen::Termination::max_iterations);
  CHECK(limit.iterations == 3);
  CHECK(limit.message.find("training (gd): stopped after 3 iterations (the limit)") == 0);
  CHECK(std::string(dpgen::to_string(limit.termination)) == "max_iterations");

  options.max_iterations = 10000;
  options.gradient_tolerance = 1e-6;
  x.setZero();
  const dpgen::TrainSummary converged = dpgen::train(bowl, gd, x, options);
  CHECK(converged.termination == dpgen::Termination::gradient_tolerance);
  CHECK(converged.converged());
  CHECK(converged.final_grad_norm <= 1e-6);
  CHECK(converged.iterations < 10000);
  CHECK(converged.message.find("training (gd): converged after ") == 0);

  int calls = 0;
  const dpgen::LossGradient poisoned = [&](const VectorXd& v, VectorXd& grad) {
    const double loss = bowl(v, grad);
    return ++calls == 4 ? std::numeric_limits<double>::quiet_NaN() : loss;
  };
  options.gradient_tolerance = 0.0;
  x.setZero();
  dpgen::TrainSummary nan;
  CHECK_NOTHROW(nan = dpgen::train(poisoned, gd, x, options));
  CHECK(nan.termination == dpgen::Termination::loss_not_finite);
  CHECK(nan.failed());
  CHECK(nan.iterations == 3);
  CHECK(nan.message == "training: loss is NaN at iteration 3");
  CHECK(std::isnan(nan.final_loss));

  int gradient_calls = 0;
  const dpgen::LossGradient bad_gradient = [&](const VectorXd& v, VectorXd& grad) {
    const double loss = bowl(v, grad);
    if (++gradient_calls == 2)
      grad[0] = std::numeric_limits<double>::infinity();
    return loss;
  };
  x.setZero();
  const dpgen::TrainSummary inf = dpgen::train(bad_gradient, gd, x, options);
  CHECK(inf.termination == dpgen::Termination::gradient_not_finite);
  CHECK(inf.message == "training: gradient is Inf at iteration 1 (index 0)");

  // The time limit: a slow loss, a limit of a few evaluations' time.
  const dpgen::LossGradient slow = [](const VectorXd& v, VectorXd& grad) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return bowl(v, grad);
  };
  options.time_limit = 0.02;
  x.setZero();
  const dpgen::TrainSummary timed = dpgen::train(slow, gd, x, options);
  CHECK(timed.termination == dpgen::Termination::time_limit);
  CHECK(timed.iterations < 10000);
  CHECK(timed.message.find("(time limit ") != std::string::npos);
}

TEST_CASE("training: bad input") {
  dpgen::GradientDescent gd({0.1});
  const dpgen::LossGradient short_gradient = [](const VectorXd& x, VectorXd& grad) {
    grad = VectorXd::Zero(x.size() - 1);
    return 1.0;
  };
  VectorXd x = VectorXd::Zero(3);
  CHECK_THROWS_WITH_AS(dpgen::train(short_gradient, gd, x),
                       "training: gradient has size 2, expected 3 at iteration 0",
                       std::invalid_argument);
  VectorXd nan_start = VectorXd::Zero(3);
  nan_start[0] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(dpgen::train(bowl, gd, nan_start),
                       "training: initial parameter vector contains nan at index 0",
                       std::invalid_argument);
}
