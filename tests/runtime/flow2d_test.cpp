// Tests of dpgen/flow2d.hpp: a step leaves a divergence-free velocity with closed walls; the
// gradient of a loss at step T with respect to the initial velocity, the initial marker and the
// inflow, through T steps with binomial checkpointing, matches central differences of the whole
// simulation and is bit-identical to the full tape's.
#include "dpgen/checkpoint.hpp"
#include "dpgen/flow2d.hpp"

#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

using dpgen_test::random_vector;
using Eigen::VectorXd;

// A marker blob as inflow near the bottom, centred at (cx, cy) cells, radius r.
VectorXd blob(int nx, int ny, double cx, double cy, double r, double amount) {
  VectorXd f = VectorXd::Zero(nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double d2 = std::pow(i + 0.5 - cx, 2) + std::pow(j + 0.5 - cy, 2);
      f[j * nx + i] = amount * std::exp(-d2 / (r * r));
    }
  return f;
}

// A random initial state: marker in [0, 1], velocities up to ~0.6 cells per step, walls zero.
VectorXd initial_state(const dpgen::Flow2d& flow, unsigned seed) {
  VectorXd state = random_vector(flow.state_size(), seed, -0.6, 0.6);
  flow.marker(state) = random_vector(flow.cells(), seed + 1, 0.0, 1.0);
  const int nx = flow.nx(), ny = flow.ny();
  auto u = flow.u(state);
  auto v = flow.v(state);
  for (int j = 0; j < ny; ++j)
    u[j * (nx + 1)] = u[j * (nx + 1) + nx] = 0.0;
  for (int i = 0; i < nx; ++i)
    v[i] = v[ny * nx + i] = 0.0;
  return state;
}

// L = 1/2 |s_T - target|^2 + w/2 (|u_T|^2 + |v_T|^2): the velocity term makes every part of the
// final state's adjoint non-zero.
struct Loss {
  const dpgen::Flow2d& flow;
  VectorXd target;
  double w = 0.1;
  double value(const VectorXd& s) const {
    return 0.5 * (flow.marker(s) - target).squaredNorm() +
           0.5 * w * (flow.u(s).squaredNorm() + flow.v(s).squaredNorm());
  }
  void add_gradient(const VectorXd& s, VectorXd& adj) const {
    flow.marker(adj) += flow.marker(s) - target;
    flow.u(adj) += w * flow.u(s);
    flow.v(adj) += w * flow.v(s);
  }
};

} // namespace

TEST_CASE("a flow step: divergence-free velocity, closed walls, few pressure iterations") {
  const int nx = 32, ny = 40;
  dpgen::Flow2d flow(nx, ny, 1.0, blob(nx, ny, 16, 5, 3, 1.0 / 3.0));
  VectorXd state = initial_state(flow, 1), next;
  for (int t = 0; t < 5; ++t) {
    flow.step(state, next);
    state = next;
    CHECK(flow.forward_pressure_summary().iterations <= 12);
  }
  // The projection's residual is 1e-10 relative to |div u1|; walls stay shut.
  CHECK(flow.divergence(state).cwiseAbs().maxCoeff() < 1e-8);
  for (int j = 0; j < ny; ++j) {
    CHECK(flow.u(state)[j * (nx + 1)] == 0.0);
    CHECK(flow.u(state)[j * (nx + 1) + nx] == 0.0);
  }
  for (int i = 0; i < nx; ++i) {
    CHECK(flow.v(state)[i] == 0.0);
    CHECK(flow.v(state)[ny * nx + i] == 0.0);
  }
  CHECK(flow.marker(state).allFinite());
}

TEST_CASE("gradient through T flow steps with Revolve matches central differences and the full "
          "tape") {
  const int nx = 8, ny = 10, steps = 6;
  for (auto advection :
       {dpgen::MarkerAdvection::semi_lagrangian, dpgen::MarkerAdvection::maccormack}) {
    CAPTURE(static_cast<int>(advection));
    dpgen::FlowOptions options;
    options.marker_advection = advection;
    options.pressure_tolerance = 1e-13;
    dpgen::Flow2d flow(nx, ny, 1.0, blob(nx, ny, 4, 2, 1.5, 0.3), options);
    const VectorXd s0 = initial_state(flow, 2);
    const Loss loss{flow, random_vector(flow.cells(), 3, 0.0, 1.0)};

    // Gradient w.r.t. the whole initial state and the inflow.
    VectorXd inflow_adj;
    const auto gradient = [&](const dpgen::CheckpointOptions& cp) {
      inflow_adj = VectorXd::Zero(flow.cells());
      return dpgen::unrolled_gradient(
          s0, steps, [&](int, const VectorXd& s, VectorXd& next) { flow.step(s, next); },
          [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
            flow.step_adjoint(s, next_adj, s_adj, inflow_adj);
          },
          [&](int t, const VectorXd& s, VectorXd& adj) {
            if (t != steps)
              return 0.0;
            loss.add_gradient(s, adj);
            return loss.value(s);
          },
          cp);
    };
    dpgen::CheckpointOptions revolve;
    revolve.strategy = dpgen::CheckpointStrategy::revolve;
    revolve.snapshots = 2;
    const dpgen::UnrolledGradient g = gradient(revolve);
    const VectorXd inflow_grad = inflow_adj;
    CHECK(g.stats.max_snapshots <= 2);
    CHECK(g.stats.recomputed_steps > 0);
    const dpgen::UnrolledGradient full = gradient({});
    CHECK(full.loss == g.loss);
    CHECK(full.state_adjoint == g.state_adjoint); // bit for bit: deterministic recomputation
    CHECK(inflow_adj == inflow_grad);

    // The loss of the whole simulation from an initial state and an inflow.
    const auto simulate = [&](const VectorXd& s_init, const VectorXd& inflow) {
      dpgen::Flow2d f(nx, ny, 1.0, inflow, options);
      VectorXd s = s_init, next;
      for (int t = 0; t < steps; ++t) {
        f.step(s, next);
        s = next;
      }
      return loss.value(s);
    };
    CHECK(simulate(s0, flow.inflow()) == doctest::Approx(g.loss).epsilon(1e-14));

    // Directional derivatives along random directions: initial velocity only (wall faces stay
    // shut), initial marker only, inflow. Central differences with step 1e-6: the semi-Lagrangian
    // traces move by ~1e-6 cells, too little to cross a cell line in these seeds, so the error is
    // the truncation O(eps^2) plus rounding O(1e-16 L / eps).
    const auto directional = [&](const VectorXd& d_state, const VectorXd& d_inflow) {
      const double eps = 1e-6;
      return (simulate(s0 + eps * d_state, flow.inflow() + eps * d_inflow) -
              simulate(s0 - eps * d_state, flow.inflow() - eps * d_inflow)) /
             (2 * eps);
    };
    for (unsigned seed : {10u, 20u, 30u}) {
      CAPTURE(seed);
      VectorXd d_velocity = initial_state(flow, seed);
      flow.marker(d_velocity).setZero();
      const VectorXd zero_inflow = VectorXd::Zero(flow.cells());
      const double fd_velocity = directional(d_velocity, zero_inflow);
      CHECK(g.state_adjoint.dot(d_velocity) == doctest::Approx(fd_velocity).epsilon(1e-6));

      VectorXd d_marker = VectorXd::Zero(flow.state_size());
      flow.marker(d_marker) = random_vector(flow.cells(), seed + 1);
      CHECK(g.state_adjoint.dot(d_marker) ==
            doctest::Approx(directional(d_marker, zero_inflow)).epsilon(1e-6));

      const VectorXd d_inflow = random_vector(flow.cells(), seed + 2);
      CHECK(
          inflow_grad.dot(d_inflow) ==
          doctest::Approx(directional(VectorXd::Zero(flow.state_size()), d_inflow)).epsilon(1e-6));
    }
  }
}

TEST_CASE("flow2d rejects bad input clearly") {
  CHECK_THROWS_WITH_AS(dpgen::Flow2d(1, 4, 1.0, VectorXd::Zero(4)),
                       "flow2d: need at least 2x2 cells and h > 0 (got 1x4, h = 1)",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::Flow2d(4, 4, 1.0, VectorXd::Zero(5)),
                       "flow2d: inflow has size 5, expected 16", std::invalid_argument);
  dpgen::Flow2d flow(4, 4, 1.0, VectorXd::Zero(16));
  VectorXd next;
  CHECK_THROWS_WITH_AS(flow.step(VectorXd::Zero(3), next),
                       "flow2d step: state has size 3, expected 56", std::invalid_argument);
  // A NaN velocity would trace back to no cell at all.
  VectorXd state = VectorXd::Zero(flow.state_size());
  flow.u(state)[6] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(flow.step(state, next), "flow2d step: state contains nan at index 22",
                       std::invalid_argument);
}
