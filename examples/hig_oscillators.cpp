// The Physics-based Deep Learning book's "Coupled Oscillators with Half-Inverse Gradients"
// (physgrad-hig-code.ipynb): a network maps a target state of two coupled, controlled
// oscillators to the 24 control values that steer the 24 RK4 steps from that state back to
// it. Trained three ways, as the notebook does: Adam on the differentiable-physics gradient
// ("GD"), scale-invariant physics (SIP: a per-sample pseudo-inverse of the physics Jacobian,
// then Adam on the proxy loss |u(theta) - u'|^2; the physical-gradient update), and
// half-inverse gradients (HIG: the SVD of the joint physics-and-network Jacobian of a batch).
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "dpgen/jacobian.hpp"
#include "dpgen/nn.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/physgrad.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// The notebook's physics: Nx = 2 oscillators, state s = (x_0, x_1, v_0, v_1),
// ds/dt = M s + b u with x' = v, v' = -x + 0.2 lap(x) + u e_last (lap with the '0' boundary:
// [[-1, 1], [1, -1]]), 24 RK4 steps of DT = 0.5, the control constant within a step.
constexpr int kOscillators = 2, kState = 2 * kOscillators, kSteps = 24;
constexpr double kDt = 0.5, kCoupling = 0.2;

struct Oscillators {
  MatrixXd m = MatrixXd::Zero(kState, kState);
  VectorXd b = VectorXd::Zero(kState);
  Oscillators() {
    const int n = kOscillators;
    for (int i = 0; i < n; ++i) {
      m(i, n + i) = 1.0;  // x_i' = v_i
      m(n + i, i) = -1.0; // v_i' = -x_i + ...
      if (i > 0) {        // ... + 0.2 (x_{i-1} - 2 x_i + x_{i+1}), ends -1 instead of -2
        m(n + i, i - 1) += kCoupling;
        m(n + i, i) -= kCoupling;
      }
      if (i < n - 1) {
        m(n + i, i + 1) += kCoupling;
        m(n + i, i) -= kCoupling;
      }
    }
    b[kState - 1] = 1.0; // the control acts on the last oscillator's velocity
  }
  VectorXd rhs(const VectorXd& s, double u) const { return m * s + b * u; }
  // s' = s + dt/6 (k1 + 2 k2 + 2 k3 + k4).
  VectorXd step(const VectorXd& s, double u) const {
    const VectorXd k1 = rhs(s, u), k2 = rhs(s + 0.5 * kDt * k1, u);
    const VectorXd k3 = rhs(s + 0.5 * kDt * k2, u), k4 = rhs(s + kDt * k3, u);
    return s + kDt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  // The reverse of step(): given s'_adj, returns s_adj and adds to u_adj. The step is linear,
  // so no primal is needed: each stage k = M s_k + b u gives s_k_adj = M^T k_adj, u_adj += b.k_adj.
  VectorXd step_adjoint(const VectorXd& out_adj, double& u_adj) const {
    VectorXd s_adj = out_adj;
    VectorXd k4_adj = kDt / 6.0 * out_adj, k3_adj = kDt / 3.0 * out_adj;
    VectorXd k2_adj = kDt / 3.0 * out_adj, k1_adj = kDt / 6.0 * out_adj;
    VectorXd stage = m.transpose() * k4_adj; // s4 = s + dt k3
    u_adj += b.dot(k4_adj);
    s_adj += stage;
    k3_adj += kDt * stage;
    stage = m.transpose() * k3_adj; // s3 = s + dt/2 k2
    u_adj += b.dot(k3_adj);
    s_adj += stage;
    k2_adj += 0.5 * kDt * stage;
    stage = m.transpose() * k2_adj; // s2 = s + dt/2 k1
    u_adj += b.dot(k2_adj);
    s_adj += stage;
    k1_adj += 0.5 * kDt * stage;
    s_adj += m.transpose() * k1_adj; // k1 = M s + b u
    u_adj += b.dot(k1_adj);
    return s_adj;
  }
  // The solver: 24 steps, control u[t] in step t.
  VectorXd rollout(const VectorXd& s0, const VectorXd& u) const {
    VectorXd s = s0;
    for (int t = 0; t < kSteps; ++t)
      s = step(s, u[t]);
    return s;
  }
  // (d s_T / d u)^T w.
  VectorXd rollout_vjp_control(const VectorXd& w) const {
    VectorXd u_adj = VectorXd::Zero(kSteps), s_adj = w;
    for (int t = kSteps; t-- > 0;)
      s_adj = step_adjoint(s_adj, u_adj[t]);
    return u_adj;
  }
  // (d s_T / d u) v: the rollout is linear, so this is the rollout of v from rest.
  VectorXd rollout_jvp_control(const VectorXd& v) const {
    return rollout(VectorXd::Zero(kState), v);
  }
  // d s_T / d u (4 x 24): by 4 VJPs (rows), fewer than the 24 JVPs columns would take.
  // The rollout is linear in u: the products are the same at every u.
  MatrixXd control_jacobian() const {
    return dpgen::jacobian([&](const VectorXd&, const VectorXd& v) { return rollout_jvp_control(v); },
                           [&](const VectorXd&, const VectorXd& w) { return rollout_vjp_control(w); },
                           VectorXd::Zero(kSteps), kState);
  }
};

// The notebook's network: 4 -> 20 -> 20 -> 20 -> 24, tanh, a linear last layer, Glorot weights.
dpgen::Sequential make_network() {
  dpgen::Sequential net;
  net.emplace<dpgen::Dense>(kState, 20).emplace<dpgen::Tanh>(20);
  net.emplace<dpgen::Dense>(20, 20).emplace<dpgen::Tanh>(20);
  net.emplace<dpgen::Dense>(20, 20).emplace<dpgen::Tanh>(20);
  net.emplace<dpgen::Dense>(20, kSteps);
  return net;
}

struct Problem {
  Oscillators physics;
  dpgen::Sequential net = make_network();
  MatrixXd data; // kState x N: the initial states, which are also the targets
  MatrixXd control_jacobian = physics.control_jacobian();

  // Sum over samples [begin, end) of |s_T - s*|^2, divided by `scale`; its gradient w.r.t.
  // theta (when grad is not null) through the rollout's VJP and the network's backward pass.
  double loss(const VectorXd& theta, int begin, int end, double scale, VectorXd* grad) const {
    dpgen::Sequential::Activations acts;
    VectorXd x_adj;
    if (grad)
      grad->setZero(theta.size());
    double total = 0.0;
    for (int i = begin; i < end; ++i) {
      const VectorXd target = data.col(i);
      net.forward(theta, target, acts);
      const VectorXd r = physics.rollout(target, acts.output()) - target;
      total += r.squaredNorm();
      if (grad) {
        x_adj.resize(0);
        net.backward(theta, acts, physics.rollout_vjp_control(2.0 / scale * r), x_adj, *grad);
      }
    }
    return total / scale;
  }
};

struct History {
  std::string name, color;
  std::vector<double> epoch, seconds, loss; // seconds: cumulative training time
};

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(argc, argv, "hig_oscillators",
                            "Adam vs SIP (physical gradients) vs HIG on the book's coupled oscillators");
  const int samples = args.get_int("--samples", 4096, "training samples (the notebook's 2^12)", 32);
  const double max_time = args.get_double(
      "--max-time", 20, "training seconds per method (the notebook's MAX_TIME is 100)", 0);
  const int max_epochs =
      args.get_int("--max-epochs", 1000000, "epochs per method at most (also after --max-time)", 0);
  const std::string methods = args.get_string("--methods", "gd,sip,hig", "which to run, in order");
  const int seed = args.get_int("--seed", 1, "seed of the data and of the initial weights", 0);
  // --require-reduction applies to every method run; --check-gradient also checks the
  // physics Jacobian and a block of HIG's joint Jacobian.
  const auto common = dpgen_examples::common_options(args, "hig_oscillators", false);
  const int threads = args.get_int(
      "--threads", 1, "Eigen's threads for the SVDs (0: OpenMP's default)", 0, 1024);
  if (args.finish())
    return 0;
  if (threads > 0)
    Eigen::setNbThreads(threads);

  Problem p;
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
  p.data.resize(kState, samples); // uniform [0, 1), as np.random.rand
  for (Eigen::Index i = 0; i < p.data.size(); ++i)
    p.data.data()[i] = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  const VectorXd theta0 = p.net.initialize(static_cast<std::uint64_t>(seed));
  std::printf("network: %lld parameters; physics Jacobian d s_T / d u: %d x %d\n",
              static_cast<long long>(theta0.size()), kState, kSteps);

  if (common.check) {
    // (1) d s_T / d u from VJP rows against JVP columns and central differences.
    const VectorXd s0 = p.data.col(0), u = VectorXd::LinSpaced(kSteps, -0.3, 0.4);
    const MatrixXd j_fd = dpgen::jacobian_central_difference(
        [&](const VectorXd& v) { return p.physics.rollout(s0, v); }, u);
    const MatrixXd j_columns = dpgen::jacobian_by_columns(
        [&](const VectorXd&, const VectorXd& v) { return p.physics.rollout_jvp_control(v); }, u,
        kState);
    const double e_modes = (p.control_jacobian - j_columns).cwiseAbs().maxCoeff();
    const double e_fd = (p.control_jacobian - j_fd).cwiseAbs().maxCoeff();
    std::printf("physics Jacobian: rows vs columns %.2e, rows vs central differences %.2e\n",
                e_modes, e_fd);
    // (2) the training gradient (Adam's, through physics and network) along random directions.
    const auto f = [&](const VectorXd& th, VectorXd& g) { return p.loss(th, 0, 8, 8.0, &g); };
    const double e_grad = dpgen_examples::gradient_check(f, theta0);
    // (3) one row block of HIG's joint Jacobian (sample 0) against central differences.
    const auto outputs = [&](const VectorXd& th) {
      return VectorXd(p.physics.rollout(s0, p.net(th, s0)));
    };
    MatrixXd rows(kState, theta0.size());
    dpgen::Sequential::Activations acts;
    p.net.forward(theta0, s0, acts);
    for (int c = 0; c < kState; ++c) {
      VectorXd x_adj, row = VectorXd::Zero(theta0.size());
      p.net.backward(theta0, acts, p.control_jacobian.row(c).transpose(), x_adj, row);
      rows.row(c) = row.transpose();
    }
    const double e_joint =
        (rows - dpgen::jacobian_central_difference(outputs, theta0)).cwiseAbs().maxCoeff();
    std::printf("joint Jacobian d s_T / d theta (4 x %lld): rows vs central differences %.2e\n",
                static_cast<long long>(theta0.size()), e_joint);
    const int status = dpgen_examples::report_gradient_check(e_grad);
    return (status == 0 && e_modes < 1e-12 && e_fd < 1e-7 && e_joint < 1e-7) ? 0 : 1;
  }

  const auto evaluate = [&](const VectorXd& th) { return p.loss(th, 0, samples, samples, nullptr); };
  std::vector<History> histories;
  const std::string dir = dpgen_examples::output_dir(common.out);
  std::vector<std::string> method_list; // checked before anything runs
  for (std::size_t pos = 0; pos <= methods.size();) {
    const std::size_t comma = std::min(methods.find(',', pos), methods.size());
    const std::string method = methods.substr(pos, comma - pos);
    if (method != "gd" && method != "sip" && method != "hig")
      args.fail("--methods takes gd, sip and hig, not '" + method + "'");
    method_list.push_back(method);
    pos = comma + 1;
  }
  for (const std::string& method : method_list) {
    // The notebook's settings per method.
    const int batch = method == "hig" ? 32 : 256;
    const int batches = samples / batch;
    VectorXd theta = theta0;
    History h{method == "gd" ? "Adam (GD)" : method == "sip" ? "SIP (PG)" : "HIG",
              method == "gd" ? "#1f77b4" : method == "sip" ? "#ff7f0e" : "#2ca02c", {}, {}, {}};
    dpgen::Adam adam(dpgen::AdamOptions{1e-3});
    dpgen::HigOptions hig_options; // the notebook's lr 1, exponent -1/2, truncation 1e-10
    hig_options.truncation = 1e-10;
    // SIP's local inverse: u' = u - J^+ (y - y'), truncating below 1e-5 S_max (its rcond).
    dpgen::HigOptions pinv;
    pinv.exponent = -1.0;
    pinv.truncation = 1e-5;
    int next_batch = 0; // the batch the next evaluation of `batch_loss` reads

    // Adam (GD): the gradient of the batch loss / batch. Called by Adam after each update with
    // the next batch, so each step uses a fresh batch's gradient.
    const dpgen::LossGradient gd_loss = [&](const VectorXd& th, VectorXd& g) {
      const int b = next_batch++ % batches;
      return p.loss(th, b * batch, (b + 1) * batch, batch, &g);
    };
    // SIP: y' = y - lr (y - y*) with lr = 2 / batch (the notebook's step: the pseudo-inverse of
    // d s_T/d u applied to d(loss/batch)/dy), u' from the local inverse, then the gradient of
    // the proxy loss sum |u(theta) - u'|^2 / batch for Adam.
    const dpgen::LossGradient sip_loss = [&](const VectorXd& th, VectorXd& g) {
      const int b = next_batch++ % batches;
      g.setZero(th.size());
      dpgen::Sequential::Activations acts;
      double total = 0.0;
      for (int i = b * batch; i < (b + 1) * batch; ++i) {
        const VectorXd target = p.data.col(i);
        p.net.forward(th, target, acts);
        const VectorXd u = acts.output();
        dpgen::PhysicalGradientProblem pg;
        pg.forward = [&](const VectorXd& v) { return p.physics.rollout(target, v); };
        pg.inverse = [&](const VectorXd& y_new, const VectorXd& v) -> VectorXd {
          return v + dpgen::hig_update(p.control_jacobian, p.physics.rollout(target, v) - y_new, pinv)
                         .step;
        };
        pg.loss = dpgen::l2_loss_newton(target);
        dpgen::PgOptions o;
        o.learning_rate = 2.0 / batch;
        dpgen::PgStep step;
        const VectorXd u_new = dpgen::physical_update(pg, u, o, &step);
        total += step.loss;
        VectorXd x_adj;
        p.net.backward(th, acts, 2.0 / batch * (u - u_new), x_adj, g);
      }
      return total / batch;
    };
    // HIG: the batch's stacked outputs (4 per sample), dL/dy of loss / batch, and the joint
    // Jacobian d s_T / d theta by rows: each row one backward pass of the network seeded
    // with a row of d s_T / d u (4 VJPs per sample, fewer than 1444 JVPs). Returns the loss.
    VectorXd hig_g;
    MatrixXd hig_j;
    const auto hig_batch = [&](const VectorXd& th, VectorXd& g, MatrixXd& j) {
      const int b = next_batch++ % batches;
      g.resize(kState * batch);
      j.resize(kState * batch, th.size());
      dpgen::Sequential::Activations acts;
      VectorXd x_adj, row(th.size());
      double total = 0.0;
      for (int i = 0; i < batch; ++i) {
        const VectorXd target = p.data.col(b * batch + i);
        p.net.forward(th, target, acts);
        const VectorXd r = p.physics.rollout(target, acts.output()) - target;
        total += r.squaredNorm();
        g.segment(kState * i, kState) = 2.0 / batch * r;
        for (int c = 0; c < kState; ++c) {
          row.setZero();
          x_adj.resize(0);
          p.net.backward(th, acts, p.control_jacobian.row(c).transpose(), x_adj, row);
          j.row(kState * i + c) = row.transpose();
        }
      }
      return total / batch;
    };

    const std::string csv_path = dir + method + ".csv";
    dpgen_examples::CsvLog csv(csv_path, "epoch,seconds,loss");
    const auto record = [&](int epoch, double seconds, double loss) {
      h.epoch.push_back(epoch);
      h.seconds.push_back(seconds);
      h.loss.push_back(loss);
      csv.line(std::to_string(epoch) + ',' + dpgen_examples::number(seconds) + ',' +
               dpgen_examples::number(loss));
      std::printf("%s epoch %4d  wall clock %8.3f s  loss %.6e\n", h.name.c_str(), epoch, seconds,
                  loss);
      std::fflush(stdout);
    };
    record(0, 0.0, evaluate(theta));
    double wall = 0.0, loss = 0.0;
    VectorXd grad;
    for (int epoch = 1; epoch <= max_epochs && wall < max_time; ++epoch) {
      const auto t0 = std::chrono::steady_clock::now();
      next_batch = 0;
      for (int b = 0; b < batches; ++b) {
        if (method == "hig") {
          hig_batch(theta, hig_g, hig_j); // g = dL/dy in place of hig_update's residual
          theta += dpgen::hig_update(hig_j, hig_g, hig_options).step;
        } else {
          const dpgen::LossGradient& f = method == "gd" ? gd_loss : sip_loss;
          if (b == 0)
            loss = f(theta, grad); // the first batch's gradient; later ones come from step()
          adam.step(theta, loss, grad, f);
        }
      }
      wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double l = evaluate(theta);
      if (!std::isfinite(l))
        throw std::runtime_error(h.name + ": loss is not finite after epoch " +
                                 std::to_string(epoch));
      record(epoch, wall, l);
    }
    std::printf("%s: loss %.4e -> %.4e in %d epochs, %.3g s (%.3g s per epoch)\n\n",
                h.name.c_str(), h.loss.front(), h.loss.back(), int(h.epoch.back()), wall,
                h.epoch.back() > 0 ? wall / h.epoch.back() : 0.0);
    histories.push_back(h);
  }

  std::vector<dpgen_examples::Series> by_time, by_epoch;
  for (const History& h : histories) {
    by_time.push_back({h.name, h.seconds, h.loss, h.color});
    by_epoch.push_back({h.name, h.epoch, h.loss, h.color});
  }
  dpgen_examples::write_svg_plot(dir + "loss_time.svg", "coupled oscillators: training loss",
                                 "wall clock time [s]", "loss per sample", by_time, true);
  dpgen_examples::write_svg_plot(dir + "loss_epoch.svg", "coupled oscillators: training loss",
                                 "epoch", "loss per sample", by_epoch, true);
  std::printf("wrote %s{gd,sip,hig}.csv %sloss_time.svg %sloss_epoch.svg\n", dir.c_str(),
              dir.c_str(), dir.c_str());
  for (const History& h : histories)
    if (dpgen_examples::check_reduction(h.loss.front() / h.loss.back(), common.require))
      return 1;
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
