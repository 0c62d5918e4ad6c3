// Progress lines and output folders shared by the examples.
#pragma once

#include "csv_log.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>
#include <string>

namespace dpgen_examples {

/// One line per iteration: iteration, loss, gradient norm, time.
inline void print_progress(const dpgen::TrainProgress& p) {
  std::printf("iter %4d  loss %.6e  |grad| %.3e  %.4f s\n", p.iteration, p.loss, p.grad_norm,
              p.seconds);
  std::fflush(stdout);
}

/// Central-difference check of a loss gradient along `trials` random
/// directions at x: returns the largest relative error
///   |(L(x + h d) - L(x - h d)) / 2h - <grad, d>| / max(|<grad, d>|, 1e-300).
template <typename LossGradient>
double gradient_check(LossGradient&& f, const Eigen::VectorXd& x, int trials = 3,
                      double h = 1e-6, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd grad, scratch;
  f(x, grad);
  double worst = 0;
  for (int t = 0; t < trials; ++t) {
    Eigen::VectorXd d(x.size());
    for (Eigen::Index i = 0; i < d.size(); ++i)
      d[i] = normal(rng);
    d /= d.norm();
    double fd = (f(x + h * d, scratch) - f(x - h * d, scratch)) / (2 * h);
    double ad = grad.dot(d);
    worst = std::max(worst, std::abs(fd - ad) / std::max(std::abs(ad), 1e-300));
  }
  return worst;
}

/// The optimizer named by --optimizer: "gd", "adam" or "lbfgs".
inline std::unique_ptr<dpgen::Optimizer> make_optimizer(const std::string& name, double lr,
                                                        const std::string& program) {
  if (name == "gd")
    return std::make_unique<dpgen::GradientDescent>(dpgen::GradientDescentOptions{lr});
  if (name == "adam")
    return std::make_unique<dpgen::Adam>(dpgen::AdamOptions{lr});
  if (name == "lbfgs")
    return std::make_unique<dpgen::Lbfgs>();
  throw std::invalid_argument(program + ": --optimizer must be gd, adam or lbfgs, not '" + name +
                              "'");
}

/// The loss per iteration, for the loss plot.
struct LossCurve {
  std::vector<double> iteration, loss;
};

void ensure_parent(const std::string& file);

/// Training options shared by the examples: at most `iters` updates, a
/// progress line per iteration and the loss curve recorded into `curve`
/// (unless `progress` is false), and the CSV log at `csv` (its folder
/// created; see attach_csv_log: it is published when the returned options,
/// and their copies, are destroyed).
inline dpgen::TrainOptions train_options(int iters, const std::string& csv, LossCurve& curve,
                                         bool progress = true) {
  dpgen::TrainOptions opts;
  opts.max_iterations = iters;
  if (progress)
    opts.callback = [&curve](const dpgen::TrainProgress& p) {
      print_progress(p);
      curve.iteration.push_back(p.iteration);
      curve.loss.push_back(p.loss);
    };
  ensure_parent(csv);
  attach_csv_log(opts, csv);
  return opts;
}

/// --check-gradient: prints the result; the exit status (1 above 1e-6).
inline int report_gradient_check(double error) {
  std::printf("gradient check: largest relative error %.2e along 3 random directions\n", error);
  return error <= 1e-6 ? 0 : 1;
}

/// --require-reduction: the exit status (1, with a message, when the loss
/// dropped less than `required` times; 0 when `required` is 0).
inline int check_reduction(double reduction, double required) {
  if (required > 0 && !(reduction >= required)) {
    std::fprintf(stderr, "error: loss dropped %.3gx, less than the required %.3gx\n", reduction,
                 required);
    return 1;
  }
  return 0;
}

/// Creates the folder a file is to be written in (for --csv PATH).
inline void ensure_parent(const std::string& file) {
  auto parent = std::filesystem::path(file).parent_path();
  if (!file.empty() && !parent.empty())
    std::filesystem::create_directories(parent);
}

/// Creates `dir` (and parents); returns it with a trailing slash.
inline std::string output_dir(const std::string& dir) {
  std::filesystem::create_directories(dir);
  return dir.empty() || dir.back() == '/' ? dir : dir + "/";
}

} // namespace dpgen_examples
