// Progress lines and output folders shared by the examples.
#pragma once

#include "dpgen/train.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <filesystem>
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
