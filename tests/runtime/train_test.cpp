// Tests of dpgen/train.hpp: progress rows (callback and CSV), stopping rules, each optimizer
// through the loop, and the NaN/Inf errors that name the iteration.
#include "dpgen/train.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;
namespace fs = std::filesystem;

// f(x) = 1/2 sum_i (i + 1) (x_i - 1)^2: minimum 0 at x = 1.
double bowl(const VectorXd& x, VectorXd& grad) {
  const VectorXd w = VectorXd::LinSpaced(x.size(), 1.0, double(x.size()));
  grad = w.cwiseProduct(x - VectorXd::Ones(x.size()));
  return 0.5 * w.dot((x - VectorXd::Ones(x.size())).cwiseAbs2());
}

// A fresh, empty directory for this test binary's logs.
fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("dpgen_train_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');)
    fields.push_back(field);
  return fields;
}

} // namespace

TEST_CASE("training log: CSV header, one row per iteration, callback rows agree") {
  const fs::path dir = scratch_dir("csv");
  const fs::path csv = dir / "log.csv";
  std::vector<dpgen::TrainProgress> rows;
  dpgen::TrainOptions options;
  options.max_iterations = 5;
  options.csv_path = csv.string();
  options.callback = [&](const dpgen::TrainProgress& p) {
    rows.push_back(p);
    // During the run only the .partial file exists, already holding every row so far.
    CHECK_FALSE(fs::exists(csv));
    CHECK(read_lines(csv.string() + ".partial").size() == rows.size() + 1);
  };
  dpgen::GradientDescent gd(0.1);
  VectorXd x = VectorXd::Zero(4);
  VectorXd g0;
  const double loss0 = bowl(x, g0);
  const dpgen::TrainSummary summary = dpgen::train(bowl, gd, x, options);

  CHECK(summary.iterations == 5);
  CHECK(summary.termination == dpgen::TrainTermination::max_iterations);
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

  CHECK_FALSE(fs::exists(csv.string() + ".partial"));
  const std::vector<std::string> lines = read_lines(csv);
  REQUIRE(lines.size() == 7);
  CHECK(lines[0] == "iter,loss,grad_norm,seconds");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<std::string> fields = split(lines[i + 1]);
    REQUIRE(fields.size() == 4);
    CHECK(std::stoi(fields[0]) == static_cast<int>(i));
    CHECK(std::strtod(fields[1].c_str(), nullptr) == rows[i].loss); // %.17g round-trips
    CHECK(std::strtod(fields[2].c_str(), nullptr) == rows[i].grad_norm);
    CHECK(std::strtod(fields[3].c_str(), nullptr) >= 0.0);
  }

  // A second run replaces the log.
  options.max_iterations = 2;
  options.callback = nullptr;
  VectorXd y = VectorXd::Zero(4);
  dpgen::train(bowl, gd, y, options);
  CHECK(read_lines(csv).size() == 4);
  fs::remove_all(dir);
}

TEST_CASE("training stops on the gradient or the loss tolerance") {
  dpgen::TrainOptions options;
  options.max_iterations = 1000;
  options.gradient_tolerance = 1e-8;
  dpgen::Lbfgs lbfgs;
  VectorXd x = VectorXd::Zero(6);
  const dpgen::TrainSummary by_gradient = dpgen::train(bowl, lbfgs, x, options);
  CHECK(by_gradient.termination == dpgen::TrainTermination::gradient_tolerance);
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
  CHECK(by_loss.termination == dpgen::TrainTermination::loss_tolerance);
  CHECK(by_loss.final_loss <= 1e-3);
  CHECK(by_loss.iterations < 1000);
  VectorXd g;
  CHECK(bowl(y, g) == by_loss.final_loss); // x is left at the reported iterate

  // Already converged: no update at all.
  VectorXd at_minimum = VectorXd::Ones(3);
  dpgen::GradientDescent gd(0.1);
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
  dpgen::GradientDescent gd(0.1);
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
  const fs::path dir = scratch_dir("nan");
  const fs::path csv = dir / "log.csv";
  // Gradient descent evaluates once per iteration: evaluation k + 1 is iteration k.
  int evaluations = 0;
  const dpgen::LossGradient poisoned = [&](const VectorXd& x, VectorXd& grad) {
    const double loss = bowl(x, grad);
    return ++evaluations == 8 ? std::numeric_limits<double>::quiet_NaN() : loss;
  };
  dpgen::TrainOptions options;
  options.max_iterations = 50;
  options.csv_path = csv.string();
  dpgen::GradientDescent gd(0.1);
  VectorXd x = VectorXd::Zero(3);
  try {
    dpgen::train(poisoned, gd, x, options);
    FAIL("expected a TrainingError");
  } catch (const dpgen::TrainingError& e) {
    CHECK(std::string(e.what()) == "training: loss is NaN at iteration 7");
    CHECK(e.iteration() == 7);
  }
  // The log is complete up to and including the offending row, and not left as .partial.
  CHECK_FALSE(fs::exists(csv.string() + ".partial"));
  const std::vector<std::string> lines = read_lines(csv);
  REQUIRE(lines.size() == 9);
  CHECK(lines.back().rfind("7,nan,", 0) == 0);

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
  fs::remove_all(dir);
}

TEST_CASE("training: bad input") {
  dpgen::GradientDescent gd(0.1);
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
  dpgen::TrainOptions unwritable;
  unwritable.csv_path = "/nonexistent-dir/log.csv";
  CHECK_THROWS_WITH_AS(
      dpgen::train(bowl, gd, x, unwritable),
      "training: cannot open log file '/nonexistent-dir/log.csv.partial' for writing",
      std::runtime_error);
}
