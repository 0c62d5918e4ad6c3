// The seed text's inverse problem ("A practical example"): find a velocity
// field u, constant in time, such that T first-order upwind steps carry the
// density d0 into d_target. Loss |d(T) - d_target|^2; the gradient comes from
// the generated upwind_step_adjoint, T steps back, accumulating u's adjoint
// over all steps; states are stored (--checkpoints 0) or recomputed with
// binomial checkpointing (--checkpoints K).
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "dpgen/checkpoint.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"
#include "kernels.hpp"
#include "upwind_step_adjoint.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Problem {
  int n, steps;
  double dx, dt;
  Eigen::VectorXd d0, target, u_true;
};

// d0: a bump at x = 0.3; the target: d0 advected by a smooth velocity field
// u_true(x) = 0.2 + 0.1 sin(2 pi x) for T steps with the same scheme.
Problem make_problem(int n, int steps) {
  Problem p{n, steps, 1.0 / n, 0.0, Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  p.dt = 0.5 * p.dx; // CFL <= 0.15 for u_true
  for (int i = 0; i < n; ++i) {
    double x = (i + 0.5) * p.dx;
    const double r = (x - 0.3) / 0.15; // compact cos^2 bump: exact zeros, no denormals
    p.d0[i] = std::abs(r) < 1 ? std::pow(std::cos(0.5 * kPi * r), 2) : 0.0;
    p.u_true[i] = 0.2 + 0.1 * std::sin(2 * kPi * x);
  }
  Eigen::VectorXd d = p.d0, next(n);
  for (int t = 0; t < steps; ++t) {
    upwind_step(d.data(), p.u_true.data(), next.data(), n, p.dt, p.dx);
    std::swap(d, next);
  }
  p.target = d;
  return p;
}

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(
      argc, argv, "advection_inverse",
      "Recover a velocity field through T upwind advection steps (dpgen).\n\n"
      "Fixed setup: periodic cells on [0, 1), dx = 1/cells, dt = dx/2; d0 a cos^2 bump of\n"
      "half-width 0.15 at x = 0.3; the target is d0 after T steps with\n"
      "u_true(x) = 0.2 + 0.1 sin(2 pi x); first guess u = 0.1; loss |d(T) - target|^2.");
  const int cells = args.get_int("--cells", 128, "grid cells on [0, 1), periodic", 3);
  const int steps = args.get_int("--steps", 100, "upwind steps T", 1);
  const int iters = args.get_int("--iters", 300, "optimizer iterations", 0);
  const std::string method = args.get_string("--optimizer", "gd", "gd, adam or lbfgs");
  const double lr = args.get_double("--lr", 0.01, "learning rate (gd, adam)", 0,
                                    std::numeric_limits<double>::infinity(), true);
  const int checkpoints = args.get_int(
      "--checkpoints", 0, "0: store every state; K > 0: Revolve with K snapshots", 0);
  const auto common = dpgen_examples::common_options(args, "advection_inverse");
  if (args.finish())
    return 0;

  const Problem p = make_problem(cells, steps);
  dpgen::CheckpointOptions cp;
  if (checkpoints > 0) {
    cp.strategy = dpgen::CheckpointStrategy::revolve;
    cp.snapshots = checkpoints;
  }
  dpgen::CheckpointStats last_stats;
  Eigen::VectorXd final_state;

  // L(u) = |d(T) - target|^2 and dL/du, through T steps.
  cp.step_assigns_every_element = true; // upwind_step writes every cell
  dpgen::CheckpointWorkspace tape;       // the states, kept from one gradient to the next
  auto loss_and_gradient = [&](const Eigen::VectorXd& u, Eigen::VectorXd& grad) {
    Eigen::VectorXd u_adj = Eigen::VectorXd::Zero(cells);
    auto step = [&](int, const Eigen::VectorXd& d, Eigen::VectorXd& next) {
      upwind_step(d.data(), u.data(), next.data(), cells, p.dt, p.dx);
    };
    auto step_adjoint = [&](int, const Eigen::VectorXd& d, const Eigen::VectorXd& next_adj,
                            Eigen::VectorXd& d_adj) {
      upwind_step_adjoint(d.data(), d_adj.data(), u.data(), u_adj.data(), next_adj.data(), cells,
                          p.dt, p.dx);
    };
    auto loss_adjoint = [&](int t, const Eigen::VectorXd& d, Eigen::VectorXd& d_adj) {
      if (t != steps)
        return 0.0;
      Eigen::VectorXd r = d - p.target;
      d_adj += 2.0 * r;
      return r.squaredNorm();
    };
    dpgen::UnrolledGradient g =
        dpgen::unrolled_gradient(p.d0, steps, step, step_adjoint, loss_adjoint, cp, &tape);
    grad = u_adj;
    last_stats = g.stats;
    final_state = g.final_state;
    return g.loss;
  };

  Eigen::VectorXd u = Eigen::VectorXd::Constant(cells, 0.1); // first guess
  const Eigen::VectorXd u_start = u;
  if (common.check) {
    Eigen::VectorXd u0 = p.u_true + Eigen::VectorXd::LinSpaced(cells, -0.05, 0.05);
    return dpgen_examples::report_gradient_check(
        dpgen_examples::gradient_check(loss_and_gradient, u0));
  }
  auto optimizer = dpgen_examples::make_optimizer(method, lr, "advection_inverse");
  dpgen_examples::LossCurve curve;
  dpgen::TrainSummary s = dpgen::train(loss_and_gradient, *optimizer, u,
                                       dpgen_examples::train_options(iters, common.csv, curve));
  const double reduction = s.initial_loss / s.final_loss;
  Eigen::VectorXd grad(cells);
  loss_and_gradient(u, grad); // final state for the pictures

  std::printf("loss %.6e -> %.6e (%.0fx lower) in %d iterations, %.2f s; %s\n", s.initial_loss,
              s.final_loss, reduction, s.iterations, s.seconds, s.message.c_str());
  std::printf("per gradient: %lld forward steps (%lld recomputed), %d states stored, peak %zu "
              "bytes of states\n",
              last_stats.forward_steps, last_stats.recomputed_steps, last_stats.max_snapshots,
              last_stats.peak_snapshot_bytes);

  const std::string dir = dpgen_examples::output_dir(common.out);
  std::vector<double> xs(cells);
  for (int i = 0; i < cells; ++i)
    xs[i] = (i + 0.5) * p.dx;
  auto vec = [](const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  dpgen_examples::write_svg_plot(dir + "loss.svg", "advection_inverse: loss", "iteration",
                                 "|d(T) - target|^2", {{"loss", curve.iteration, curve.loss}}, true);
  dpgen_examples::write_svg_plot(
      dir + "density.svg", "density after T steps", "x", "d",
      {{"d0", xs, vec(p.d0), "#999999", true},
       {"target", xs, vec(p.target), "#d62728"},
       {"d(T), optimized u", xs, vec(final_state), "#1f77b4", true}});
  dpgen_examples::write_svg_plot(dir + "velocity.svg", "velocity", "x", "u",
                                 {{"u (start)", xs, vec(u_start), "#999999", true},
                                  {"u (optimized)", xs, vec(u), "#1f77b4"},
                                  {"u used for the target", xs, vec(p.u_true), "#d62728", true}});
  std::printf("pictures: %sloss.svg %sdensity.svg %svelocity.svg\n", dir.c_str(), dir.c_str(),
              dir.c_str());
  return dpgen_examples::check_reduction(reduction, common.require);
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
