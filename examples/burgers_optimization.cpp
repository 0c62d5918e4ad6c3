// The Physics-based Deep Learning book's "Burgers Optimization with a Differentiable Physics
// Gradient": recover the initial state u0 of 1D periodic Burgers from the state at step 16,
// by plain gradient descent through 16 steps of explicit diffusion + semi-Lagrangian
// self-advection (generated adjoints of diffuse_explicit and advect_self_semi_lagrangian).
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "advect_self_semi_lagrangian_adjoint.hpp"
#include "diffuse_explicit_adjoint.hpp"
#include "dpgen/checkpoint.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"
#include "example_kernels.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// The book's setup: N cells on [-1, 1] (cell centres, periodic), 32 steps of DT = 1/32,
// NU = 0.01 / (N pi); the loss compares step 16 with the reference.
constexpr int kCells = 128;
constexpr int kSteps = 32;
constexpr int kLossStep = 16;
constexpr double kDx = 2.0 / kCells;
constexpr double kDt = 1.0 / kSteps;
const double kNu = 0.01 / (kCells * kPi);

// One solver step: u_mid = u + DT NU laplace(u), then u_next = u_mid advected by itself.
void burgers_step(const Eigen::VectorXd& u, Eigen::VectorXd& mid, Eigen::VectorXd& next) {
  diffuse_explicit(u.data(), mid.data(), kCells, kDt, kNu, kDx);
  advect_self_semi_lagrangian(mid.data(), next.data(), kCells, kDt, kDx);
}

// Where --reference points by default: data/burgers_t16_reference.txt next to
// this executable (the build copies examples/data/ there); nothing of the
// source tree is compiled in.
std::string default_reference() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = ec ? std::filesystem::path(".") : exe.parent_path();
  return (dir / "data" / "burgers_t16_reference.txt").string();
}

// The reference state at step 16: exactly kCells numbers, whitespace separated.
Eigen::VectorXd read_reference(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(
        "burgers_optimization: cannot open the reference file '" + path +
        "'; it is examples/data/burgers_t16_reference.txt of the dpgen sources, which the "
        "build copies to data/ next to this executable: give its path with --reference");
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (*end || !std::isfinite(v))
      throw std::runtime_error("burgers_optimization: '" + path + "' value " +
                               std::to_string(values.size() + 1) + " is not a finite number: '" +
                               token + "'");
    values.push_back(v);
  }
  if (values.size() != size_t(kCells))
    throw std::runtime_error("burgers_optimization: '" + path + "' holds " +
                             std::to_string(values.size()) + " values, expected " +
                             std::to_string(kCells));
  return Eigen::Map<const Eigen::VectorXd>(values.data(), kCells);
}

std::vector<double> vec(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(
      argc, argv, "burgers_optimization",
      "Recover the initial state of 1D Burgers from its state at t = 0.5 (the PBDL book's DP\n"
      "optimization, dpgen).\n\n"
      "Fixed setup, as in the book: N = 128 cells on [-1, 1], periodic; 32 steps of dt = 1/32\n"
      "(explicit diffusion with nu = 0.01/(N pi), then semi-Lagrangian self-advection); loss\n"
      "sum((u16 - reference)^2) / N at step 16; first guess u0 = 0; plain gradient descent.");
  const int iters = args.get_int("--iters", 50, "gradient descent iterations", 0);
  const double lr = args.get_double("--lr", 5.0, "learning rate", 0,
                                    std::numeric_limits<double>::infinity(), true);
  const std::string reference =
      args.get_string("--reference", default_reference(),
                      "file with the 128 reference values at step 16 (a copy of "
                      "examples/data/burgers_t16_reference.txt)");
  const auto common = dpgen_examples::common_options(args, "burgers_optimization");
  if (args.finish())
    return 0;

  const Eigen::VectorXd ref = read_reference(reference);

  // L(u0) = sum((u16 - ref)^2) / N and dL/du0, through 16 stored steps.
  Eigen::VectorXd u16;
  dpgen::CheckpointWorkspace tape; // the states, kept from one gradient to the next
  auto loss_and_gradient = [&](const Eigen::VectorXd& u0, Eigen::VectorXd& grad) {
    Eigen::VectorXd mid(kCells), mid_adj(kCells);
    auto step = [&](int, const Eigen::VectorXd& u, Eigen::VectorXd& next) {
      burgers_step(u, mid, next);
    };
    // Reverse of one step: advect adjoint into the intermediate state, then diffuse adjoint.
    auto step_adjoint = [&](int, const Eigen::VectorXd& u, const Eigen::VectorXd& next_adj,
                            Eigen::VectorXd& u_adj) {
      diffuse_explicit(u.data(), mid.data(), kCells, kDt, kNu, kDx);
      mid_adj.setZero();
      advect_self_semi_lagrangian_adjoint(mid.data(), mid_adj.data(), next_adj.data(), kCells, kDt,
                                          kDx);
      diffuse_explicit_adjoint(u.data(), u_adj.data(), mid_adj.data(), kCells, kDt, kNu, kDx);
    };
    auto loss_adjoint = [&](int t, const Eigen::VectorXd& u, Eigen::VectorXd& u_adj) {
      if (t != kLossStep)
        return 0.0;
      const Eigen::VectorXd r = u - ref;
      u_adj += (2.0 / kCells) * r;
      return r.squaredNorm() / kCells;
    };
    dpgen::UnrolledGradient g =
        dpgen::unrolled_gradient(u0, kLossStep, step, step_adjoint, loss_adjoint, {}, &tape);
    grad = g.state_adjoint;
    u16 = g.final_state;
    return g.loss;
  };

  // For comparison: the loss of the initial state the book shows as ground truth.
  std::vector<double> xs(kCells);
  Eigen::VectorXd u_book(kCells);
  for (int i = 0; i < kCells; ++i) {
    xs[i] = -1.0 + (i + 0.5) * kDx;
    u_book[i] = -std::sin(kPi * xs[i]);
  }
  Eigen::VectorXd grad(kCells);
  const double book_loss = loss_and_gradient(u_book, grad);
  std::printf("loss of u0 = -sin(pi x) (the book's ground-truth initial state): %.6e\n", book_loss);

  if (common.check) {
    const Eigen::VectorXd at = u_book + Eigen::VectorXd::LinSpaced(kCells, -0.05, 0.05);
    return dpgen_examples::report_gradient_check(
        dpgen_examples::gradient_check(loss_and_gradient, at));
  }

  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(kCells); // the book's starting guess
  dpgen::GradientDescent optimizer({lr});
  dpgen_examples::LossCurve curve;
  const auto start = std::chrono::steady_clock::now();
  const dpgen::TrainSummary s = dpgen::train(loss_and_gradient, optimizer, u0,
                                             dpgen_examples::train_options(iters, common.csv, curve));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  loss_and_gradient(u0, grad); // u16 of the final u0, for the pictures

  std::printf("loss %.6e -> %.6e (%.1fx lower) in %d iterations; %s\n", s.initial_loss,
              s.final_loss, s.initial_loss / s.final_loss, s.iterations, s.message.c_str());
  std::printf("wall time of the %d iterations: %.3g s (%d loss+gradient evaluations through %d "
              "steps, iteration 0 included)\n",
              s.iterations, wall, s.evaluations, kLossStep);

  // States of the whole 32-step simulation from the optimized u0.
  Eigen::VectorXd u = u0, mid(kCells), next(kCells);
  for (int t = 0; t < kSteps; ++t) {
    burgers_step(u, mid, next);
    std::swap(u, next);
  }
  const std::string dir = dpgen_examples::output_dir(common.out);
  dpgen_examples::write_svg_plot(dir + "loss.svg", "burgers_optimization: loss", "iteration",
                                 "sum((u16 - ref)^2) / N", {{"loss", curve.iteration, curve.loss}}, true);
  dpgen_examples::write_svg_plot(dir + "state_t16.svg", "states from the optimized u0", "x", "u",
                                 {{"reference (t = 0.5)", xs, vec(ref), "#2ca02c"},
                                  {"u16 (t = 0.5)", xs, vec(u16), "#1f77b4", true},
                                  {"u32 (t = 1)", xs, vec(u), "#999999", true}});
  dpgen_examples::write_svg_plot(
      dir + "initial_state.svg", "initial state u0", "x", "u",
      {{"-sin(pi x)", xs, vec(u_book), "#2ca02c"}, {"optimized u0", xs, vec(u0), "#1f77b4"}});
  std::printf("pictures: %sloss.svg %sstate_t16.svg %sinitial_state.svg\n", dir.c_str(),
              dir.c_str(), dir.c_str());

  if (dpgen_examples::check_reduction(s.initial_loss / s.final_loss, common.require))
    return 1;
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
