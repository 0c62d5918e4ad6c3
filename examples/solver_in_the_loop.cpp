// Solver in the loop (seed dp-discussion-time-steps.txt): a small network corrects a coarse 1D
// Burgers solver after every step. Trained (a) with DP gradients through unrolled solver steps
// (generated kernel adjoints + the network's adjoint) and (b) supervised on one-step pairs.
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "advect_self_semi_lagrangian_adjoint.hpp"
#include "diffuse_explicit_adjoint.hpp"
#include "dpgen/checkpoint.hpp"
#include "dpgen/nn.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"
#include "example_kernels.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;
using Trajectory = std::vector<VectorXd>; // states at coarse steps 0, 1, ...

constexpr double kPi = 3.14159265358979323846;

// Two resolutions of the same solver on x in [-1, 1], periodic: the coarse one takes steps of
// dt, the fine one `ratio` times more cells and `ratio` substeps of dt / ratio per coarse step.
struct Setup {
  int coarse = 32, ratio = 4;
  double dt = 1.0 / 32, nu = 0.01 / kPi;
  int fine() const { return coarse * ratio; }
  double dx_coarse() const { return 2.0 / coarse; }
  double dx_fine() const { return 2.0 / fine(); }
};

// One Burgers step on n cells: explicit diffusion, then semi-Lagrangian self-advection.
void burgers_step(const VectorXd& u, VectorXd& mid, VectorXd& next, int n, double dt, double nu,
                  double dx) {
  diffuse_explicit(u.data(), mid.data(), n, dt, nu, dx);
  advect_self_semi_lagrangian(mid.data(), next.data(), n, dt, dx);
}

// Uniform on [0, 1) from 53 raw bits: the same numbers on every platform.
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// A random smooth periodic initial state on the fine grid: four sine modes with random
// amplitudes (falling off as 1/k) and phases, scaled to a peak |u| in [0.25, 1].
VectorXd random_initial_state(std::mt19937_64& rng, const Setup& s) {
  VectorXd u = VectorXd::Zero(s.fine());
  for (int k = 1; k <= 4; ++k) {
    const double a = (2 * uniform(rng) - 1) / k, phase = 2 * kPi * uniform(rng);
    for (int i = 0; i < s.fine(); ++i)
      u[i] += a * std::sin(kPi * k * (-1.0 + (i + 0.5) * s.dx_fine()) + phase);
  }
  const double peak = 0.25 + 0.75 * uniform(rng);
  return u * (peak / u.cwiseAbs().maxCoeff());
}

// Cell averages of the fine state on the coarse grid.
VectorXd downsample(const VectorXd& fine, const Setup& s) {
  VectorXd c(s.coarse);
  for (int j = 0; j < s.coarse; ++j)
    c[j] = fine.segment(j * s.ratio, s.ratio).mean();
  return c;
}

// The reference: the fine solver from `initial`, downsampled at every coarse step.
Trajectory reference_trajectory(const VectorXd& initial, int steps, const Setup& s) {
  Trajectory r{downsample(initial, s)};
  VectorXd u = initial, mid(s.fine()), next(s.fine());
  for (int t = 0; t < steps; ++t) {
    for (int k = 0; k < s.ratio; ++k) {
      burgers_step(u, mid, next, s.fine(), s.dt / s.ratio, s.nu, s.dx_fine());
      std::swap(u, next);
    }
    r.push_back(downsample(u, s));
  }
  return r;
}

// The coarse solver with an optional learned correction: u_{t+1} = P(u_t) + net(P(u_t)).
class CorrectedSolver {
public:
  CorrectedSolver(const Setup& s, const dpgen::Sequential& net) : s_(s), net_(net) {}

  // u_{t+1} from u_t; params == nullptr: the coarse solver alone.
  void step(const VectorXd& u, VectorXd& next, const VectorXd* params) {
    solve(u);
    next = p_;
    if (params) {
      net_.forward(*params, p_, acts_);
      next += acts_.output();
    }
  }

  // Adds (d u_{t+1} / d u_t)^T next_adj into u_adj and (d u_{t+1} / d params)^T next_adj
  // into params_adj, recomputing the step from u_t.
  void step_adjoint(const VectorXd& u, const VectorXd& next_adj, VectorXd& u_adj,
                    const VectorXd& params, VectorXd& params_adj) {
    solve(u);
    net_.forward(params, p_, acts_);
    p_adj_ = next_adj; // the identity path of P + net(P)
    net_.backward(params, acts_, next_adj, p_adj_, params_adj);
    mid_adj_.setZero(s_.coarse);
    advect_self_semi_lagrangian_adjoint(mid_.data(), mid_adj_.data(), p_adj_.data(), s_.coarse,
                                        s_.dt, s_.dx_coarse());
    diffuse_explicit_adjoint(u.data(), u_adj.data(), mid_adj_.data(), s_.coarse, s_.dt, s_.nu,
                             s_.dx_coarse());
  }

  // The coarse solver's step alone.
  const VectorXd& solve(const VectorXd& u) {
    mid_.resize(s_.coarse);
    p_.resize(s_.coarse);
    burgers_step(u, mid_, p_, s_.coarse, s_.dt, s_.nu, s_.dx_coarse());
    return p_;
  }

  Trajectory rollout(const VectorXd& initial, int steps, const VectorXd* params) {
    Trajectory r{initial};
    VectorXd next;
    for (int t = 0; t < steps; ++t) {
      step(r.back(), next, params);
      r.push_back(next);
    }
    return r;
  }

private:
  Setup s_;
  const dpgen::Sequential& net_;
  dpgen::Sequential::Activations acts_;
  VectorXd mid_, p_, p_adj_, mid_adj_;
};

// sqrt(sum |u_t - r_t|^2) / sqrt(sum |r_t|^2) over all steps after the first and all rollouts.
double relative_l2(const std::vector<Trajectory>& u, const std::vector<Trajectory>& r) {
  double err = 0, norm = 0;
  for (size_t k = 0; k < u.size(); ++k)
    for (size_t t = 1; t < u[k].size(); ++t) {
      err += (u[k][t] - r[k][t]).squaredNorm();
      norm += r[k][t].squaredNorm();
    }
  return std::sqrt(err / norm);
}

std::vector<double> vec(const VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(
      argc, argv, "solver_in_the_loop",
      "Train a network that corrects a coarse Burgers solver, with DP gradients through the\n"
      "solver and supervised on one-step pairs.\n\n"
      "Fixed setup: x in [-1, 1], periodic; coarse steps of dt = 1/32 (explicit diffusion, then\n"
      "semi-Lagrangian self-advection); the reference runs ratio x the cells with ratio\n"
      "substeps, averaged onto the coarse cells; initial states: four sine modes with random\n"
      "amplitudes (falling as 1/k) and phases, peak |u| in [0.25, 1]; held-out rollouts run\n"
      "4 x --unroll steps.");
  Setup s;
  const double inf = std::numeric_limits<double>::infinity();
  s.coarse = args.get_int("--cells", 32, "coarse grid cells on [-1, 1]", 3);
  s.ratio =
      args.get_int("--ratio", 4, "the reference has ratio times the cells and time steps", 1);
  s.nu = args.get_double("--nu", s.nu, "viscosity (0.01/pi)", 0);
  const int train_ics = args.get_int("--train", 8, "training initial conditions", 1);
  const int test_ics = args.get_int("--test", 16, "held-out initial conditions", 1);
  const int horizon = args.get_int("--horizon", 32, "steps of the training trajectories", 1);
  const int unroll =
      args.get_int("--unroll", 16, "solver steps unrolled in DP training (at most --horizon)", 1);
  const int iters = args.get_int("--iters", 800, "Adam iterations of each training", 0);
  const double lr =
      args.get_double("--lr", 1e-3, "Adam learning rate (both trainings)", 0, inf, true);
  const int channels = args.get_int("--channels", 8, "hidden channels of the network", 1);
  const int kernel = args.get_int("--kernel", 5, "convolution width (odd, at most --cells)", 1);
  const int hidden = args.get_int("--hidden", 1, "hidden convolution + tanh layers", 0);
  const int seed = args.get_int("--seed", 1, "seed of the initial conditions and the network");
  const std::string csv =
      args.get_string("--csv", "", "CSV log of the DP training; none: no log");
  const std::string csv_sup = args.get_string("--csv-supervised", "",
                                              "CSV log of the supervised training; none: no log");
  const std::string out = args.get_string("--out", "out/solver_in_the_loop", "folder for pictures");
  const double require_reduction = args.get_double(
      "--require-reduction", 0.0,
      "fail unless the DP training loss drops by this factor (0: no requirement)", 0);
  const int require_dp_better = args.get_int(
      "--require-dp-better", 0, "1: fail unless the DP-trained rollout error is the lowest", 0, 1);
  const int check = args.get_int("--check-gradient", 0,
                                 "1: compare both training gradients with central differences and "
                                 "exit (status 1 if a relative error exceeds 1e-6)",
                                 0, 1);
  if (args.finish())
    return 0;
  if (unroll > horizon)
    args.fail("--unroll must be at most --horizon (" + std::to_string(horizon) + "), got " +
              std::to_string(unroll));
  if (kernel % 2 == 0 || kernel > s.coarse)
    args.fail("--kernel must be odd and at most --cells (" + std::to_string(s.coarse) +
              "), got " + std::to_string(kernel));
  const auto start = std::chrono::steady_clock::now();

  // Data: reference trajectories, training ones over the horizon, held-out ones (from their
  // own random stream) as long as the rollouts.
  const int rollout_steps = 4 * unroll;
  std::mt19937_64 train_rng(static_cast<std::uint64_t>(seed)),
      test_rng(static_cast<std::uint64_t>(seed) + 0x9e3779b97f4a7c15ull);
  std::vector<Trajectory> train_ref, test_ref;
  for (int k = 0; k < train_ics; ++k)
    train_ref.push_back(reference_trajectory(random_initial_state(train_rng, s), horizon, s));
  for (int k = 0; k < test_ics; ++k)
    test_ref.push_back(reference_trajectory(random_initial_state(test_rng, s), rollout_steps, s));

  // The network: (periodic conv, tanh) x hidden, periodic conv. The last layer starts at zero,
  // so both trainings start from the uncorrected solver (their iteration 0), with the same
  // parameters.
  const int n = s.coarse;
  dpgen::Sequential net;
  for (int l = 0; l < hidden; ++l)
    net.emplace<dpgen::Conv1d>(l == 0 ? 1 : channels, channels, n, kernel)
        .emplace<dpgen::Tanh>(channels * n);
  net.emplace<dpgen::Conv1d>(channels, 1, n, kernel);
  VectorXd theta0 = net.initialize(static_cast<std::uint64_t>(seed));
  const size_t last = net.size() - 1;
  theta0.segment(net.offset(last), net.layer(last).parameter_count()).setZero();
  CorrectedSolver solver(s, net);

  // (a) DP: windows of `unroll` steps starting from reference states every unroll/2 steps;
  // loss = mean over windows of sum_t |u_t - r_t|^2 / n, gradient through every step.
  std::vector<std::pair<int, int>> windows; // (trajectory, first step)
  const int stride = std::max(1, unroll / 2);
  for (int k = 0; k < train_ics; ++k)
    for (int t0 = 0; t0 + unroll <= horizon; t0 += stride)
      windows.push_back({k, t0});
  const double window_weight = 1.0 / (double(n) * double(windows.size()));
  auto dp_loss = [&](const VectorXd& theta, VectorXd& grad) {
    grad.setZero(theta.size());
    double loss = 0;
    for (auto [k, t0] : windows) {
      const Trajectory& ref = train_ref[size_t(k)];
      auto step = [&](int, const VectorXd& u, VectorXd& next) { solver.step(u, next, &theta); };
      auto step_adjoint = [&](int, const VectorXd& u, const VectorXd& next_adj, VectorXd& u_adj) {
        solver.step_adjoint(u, next_adj, u_adj, theta, grad);
      };
      auto loss_adjoint = [&](int t, const VectorXd& u, VectorXd& u_adj) {
        if (t == 0)
          return 0.0;
        const VectorXd r = u - ref[size_t(t0 + t)];
        u_adj += 2.0 * window_weight * r;
        return window_weight * r.squaredNorm();
      };
      loss +=
          dpgen::unrolled_gradient(ref[size_t(t0)], unroll, step, step_adjoint, loss_adjoint).loss;
    }
    return loss;
  };

  // (b) Supervised: net(P(r_t)) should be r_{t+1} - P(r_t), for every precomputed pair; the
  // solver only makes the inputs, it is not in the loss.
  std::vector<VectorXd> inputs, targets;
  for (const Trajectory& ref : train_ref)
    for (int t = 0; t < horizon; ++t) {
      inputs.push_back(solver.solve(ref[size_t(t)]));
      targets.push_back(ref[size_t(t + 1)] - inputs.back());
    }
  const double pair_weight = 1.0 / (double(n) * double(inputs.size()));
  auto supervised_loss = [&](const VectorXd& theta, VectorXd& grad) {
    grad.setZero(theta.size());
    double loss = 0;
    dpgen::Sequential::Activations acts;
    VectorXd x_adj;
    for (size_t p = 0; p < inputs.size(); ++p) {
      net.forward(theta, inputs[p], acts);
      const VectorXd r = acts.output() - targets[p];
      loss += pair_weight * r.squaredNorm();
      x_adj.setZero(n);
      net.backward(theta, acts, (2.0 * pair_weight) * r, x_adj, grad);
    }
    return loss;
  };

  if (check) {
    // At a network with small random weights in every layer.
    const VectorXd at = net.initialize(static_cast<std::uint64_t>(seed) + 1) * 0.3;
    const double e_dp = dpgen_examples::gradient_check(dp_loss, at);
    const double e_sup = dpgen_examples::gradient_check(supervised_loss, at);
    std::printf("gradient check: largest relative error DP %.2e, supervised %.2e along 3 random "
                "directions\n",
                e_dp, e_sup);
    return e_dp <= 1e-6 && e_sup <= 1e-6 ? 0 : 1;
  }
  std::printf("coarse %d cells, reference %d cells and %d substeps per step; %d training "
              "trajectories of %d steps (DP: %zu windows of %d steps; supervised: %zu one-step "
              "pairs); network %zu layers, %lld parameters\n",
              n, s.fine(), s.ratio, train_ics, horizon, windows.size(), unroll, inputs.size(),
              net.size(), static_cast<long long>(net.parameter_count()));
  auto run = [&](const char* name, const dpgen::LossGradient& f, const std::string& log,
                 std::vector<double>& curve) {
    std::printf("%s training (Adam, lr %g, %d iterations)\n", name, lr, iters);
    VectorXd theta = theta0;
    dpgen::Adam adam(dpgen::AdamOptions{lr});
    dpgen::TrainOptions opts;
    opts.max_iterations = iters;
    opts.callback = [&](const dpgen::TrainProgress& p) {
      dpgen_examples::print_progress(p);
      curve.push_back(p.loss);
    };
    dpgen_examples::ensure_parent(log);
    const auto csv_log = dpgen_examples::attach_csv_log(opts, log);
    const dpgen::TrainSummary sum = dpgen::train(f, adam, theta, opts);
    csv_log->close();
    std::printf("%s: loss %.6e -> %.6e (%.1fx lower), %.2f s\n", name, sum.initial_loss,
                sum.final_loss, sum.initial_loss / sum.final_loss, sum.seconds);
    return std::make_pair(theta, sum);
  };
  std::vector<double> dp_curve, sup_curve;
  const auto [theta_dp, dp_summary] = run("DP", dp_loss, csv, dp_curve);
  const VectorXd theta_sup = run("supervised", supervised_loss, csv_sup, sup_curve).first;

  {
    VectorXd g;
    std::printf("cross-check on the training data: DP-trained net's one-step loss %.6e, "
                "supervised net's unrolled loss %.6e\n",
                supervised_loss(theta_dp, g), dp_loss(theta_sup, g));
  }

  // Held-out rollouts from the downsampled initial states, 4x the unrolled horizon.
  std::vector<Trajectory> source, corrected, supervised;
  for (const Trajectory& ref : test_ref) {
    source.push_back(solver.rollout(ref[0], rollout_steps, nullptr));
    corrected.push_back(solver.rollout(ref[0], rollout_steps, &theta_dp));
    supervised.push_back(solver.rollout(ref[0], rollout_steps, &theta_sup));
  }
  std::printf("held out: %d initial conditions, rollouts of %d steps (4x the %d unrolled "
              "steps); relative L2 error over all their states\n",
              test_ics, rollout_steps, unroll);
  const double e_source = relative_l2(source, test_ref), e_dp = relative_l2(corrected, test_ref),
               e_sup = relative_l2(supervised, test_ref);
  std::printf("rollout rel-L2 error: source=%.4g corrected=%.4g supervised=%.4g\n", e_source, e_dp,
              e_sup);

  // Pictures: both training curves; the first held-out rollout's last state; the error of
  // every step of the held-out rollouts.
  const std::string dir = dpgen_examples::output_dir(out);
  auto iterations = [](const std::vector<double>& c) {
    std::vector<double> x(c.size());
    for (size_t i = 0; i < c.size(); ++i)
      x[i] = double(i);
    return x;
  };
  dpgen_examples::write_svg_plot(
      dir + "loss.svg", "solver_in_the_loop: training losses", "iteration", "loss",
      {{"DP, unrolled", iterations(dp_curve), dp_curve, "#1f77b4"},
       {"supervised, one step", iterations(sup_curve), sup_curve, "#ff7f0e"}},
      true);
  std::vector<double> xs(static_cast<size_t>(n)), steps(static_cast<size_t>(rollout_steps + 1));
  for (int i = 0; i < n; ++i)
    xs[size_t(i)] = -1.0 + (i + 0.5) * s.dx_coarse();
  for (size_t t = 0; t < steps.size(); ++t)
    steps[t] = double(t);
  char title[96];
  std::snprintf(title, sizeof title, "held-out rollout 1 of %d, step %d (t = %g)", test_ics,
                rollout_steps, rollout_steps * s.dt);
  dpgen_examples::write_svg_plot(
      dir + "rollout.svg", title, "x", "u",
      {{"reference", xs, vec(test_ref[0].back()), "#2ca02c"},
       {"source (no correction)", xs, vec(source[0].back()), "#999999", true},
       {"corrected (DP)", xs, vec(corrected[0].back()), "#1f77b4"},
       {"supervised", xs, vec(supervised[0].back()), "#ff7f0e", true}});
  auto error_per_step = [&](const std::vector<Trajectory>& u) {
    std::vector<double> e(steps.size());
    for (size_t t = 0; t < steps.size(); ++t) {
      double err = 0, norm = 0;
      for (size_t k = 0; k < u.size(); ++k) {
        err += (u[k][t] - test_ref[k][t]).squaredNorm();
        norm += test_ref[k][t].squaredNorm();
      }
      e[t] = std::sqrt(err / norm);
    }
    return e;
  };
  dpgen_examples::write_svg_plot(dir + "error.svg", "held-out rollouts: relative L2 error per step",
                                 "step", "|u - ref| / |ref|",
                                 {{"source", steps, error_per_step(source), "#999999"},
                                  {"corrected (DP)", steps, error_per_step(corrected), "#1f77b4"},
                                  {"supervised", steps, error_per_step(supervised), "#ff7f0e"}});
  std::printf("pictures: %sloss.svg %srollout.svg %serror.svg\n", dir.c_str(), dir.c_str(),
              dir.c_str());
  std::printf("total wall time %.2f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  const double reduction = dp_summary.initial_loss / dp_summary.final_loss;
  if (require_reduction > 0 && !(reduction >= require_reduction)) {
    std::fprintf(stderr, "error: DP training loss dropped %.3gx, less than the required %.3gx\n",
                 reduction, require_reduction);
    return 1;
  }
  if (require_dp_better && !(e_dp < e_sup && e_dp < e_source)) {
    std::fprintf(stderr, "error: the DP-trained correction is not the most accurate "
                         "(--require-dp-better)\n");
    return 1;
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
