// Tests of dpgen/solvers/flow2d.hpp: a step leaves a divergence-free velocity with closed walls;
// the gradient of a loss at step T with respect to the initial velocity, the initial marker and the
// inflow, through T steps with binomial checkpointing, matches central differences of the whole
// simulation and is bit-identical to the full tape's.
#include "dpgen/checkpoint.hpp"
#include "dpgen/solvers/flow2d.hpp"

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

// A random initial state: marker in [0, 1], velocities up to ~0.6 cells per step, walls zero on
// closed axes; on periodic ones the last face is a copy of the first (as a step leaves it).
VectorXd initial_state(const dpgen::Flow2d& flow, unsigned seed) {
  VectorXd state = random_vector(flow.state_size(), seed, -0.6, 0.6);
  flow.marker(state) = random_vector(flow.cells(), seed + 1, 0.0, 1.0);
  const int nx = flow.nx(), ny = flow.ny();
  auto u = flow.u(state);
  auto v = flow.v(state);
  for (int j = 0; j < ny; ++j) {
    if (flow.periodic_x())
      u[j * (nx + 1) + nx] = u[j * (nx + 1)];
    else
      u[j * (nx + 1)] = u[j * (nx + 1) + nx] = 0.0;
  }
  for (int i = 0; i < nx; ++i) {
    if (flow.periodic_y())
      v[ny * nx + i] = v[i];
    else
      v[i] = v[ny * nx + i] = 0.0;
  }
  return state;
}

// The state (or inflow, force) moved by (mx, my) cells on a fully periodic grid: what was at cell
// (i, j) is at (i + mx, j + my) mod (nx, ny); the copy faces follow their originals.
VectorXd shifted(const dpgen::Flow2d& flow, const VectorXd& state, int mx, int my) {
  const int nx = flow.nx(), ny = flow.ny();
  VectorXd out(state.size());
  const auto wrap = [](int a, int n) { return ((a % n) + n) % n; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      flow.marker(out)[wrap(j + my, ny) * nx + wrap(i + mx, nx)] = flow.marker(state)[j * nx + i];
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i)
      flow.u(out)[wrap(j + my, ny) * (nx + 1) + wrap(i + mx, nx)] =
          flow.u(state)[j * (nx + 1) + (i % nx)];
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i)
      flow.v(out)[wrap(j + my, ny) * nx + wrap(i + mx, nx)] = flow.v(state)[(j % ny) * nx + i];
  for (int j = 0; j < ny; ++j)
    flow.u(out)[j * (nx + 1) + nx] = flow.u(out)[j * (nx + 1)];
  for (int i = 0; i < nx; ++i)
    flow.v(out)[ny * nx + i] = flow.v(out)[i];
  return out;
}

VectorXd shifted_cells(int nx, int ny, const VectorXd& f, int mx, int my) {
  VectorXd out(f.size());
  const auto wrap = [](int a, int n) { return ((a % n) + n) % n; };
  for (Eigen::Index b = 0; b < f.size() / (nx * ny); ++b)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        out[b * nx * ny + wrap(j + my, ny) * nx + wrap(i + mx, nx)] = f[b * nx * ny + j * nx + i];
  return out;
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

TEST_CASE("flow steps reuse one CG workspace: pressure solves allocate no new buffers, and the "
          "steps match a fresh solver's bit for bit") {
  const int nx = 16, ny = 12;
  const VectorXd inflow = blob(nx, ny, 8, 3, 2, 0.3);
  dpgen::Flow2d flow(nx, ny, 1.0, inflow);
  const dpgen::CgWorkspace& w = flow.pressure_workspace();
  VectorXd state = initial_state(flow, 3), next;
  flow.step(state, next);
  REQUIRE(w.r.size() == flow.cells());
  const double* buffers[4] = {w.r.data(), w.z.data(), w.p.data(), w.q.data()};
  VectorXd state_adj = VectorXd::Zero(flow.state_size()), inflow_adj = VectorXd::Zero(flow.cells());
  for (int t = 0; t < 4; ++t) {
    state = next;
    flow.step(state, next);
    flow.step_adjoint(state, next, state_adj, inflow_adj); // a backward pressure solve too
    const double* now[4] = {w.r.data(), w.z.data(), w.p.data(), w.q.data()};
    for (int i = 0; i < 4; ++i)
      CHECK(now[i] == buffers[i]);
    CHECK(flow.forward_pressure_summary().converged());
    CHECK(flow.backward_pressure_summary().converged());
  }
  // A fresh solver (fresh workspace) recomputes the last step to the same bits.
  dpgen::Flow2d fresh(nx, ny, 1.0, inflow);
  VectorXd again;
  fresh.step(state, again);
  CHECK(again == next);
}

// The gradient of a loss at step T w.r.t. the initial state, the inflow and a (constant) body
// force field, through T steps with Revolve (2 snapshots): bit-identical to the full tape's,
// and against central differences of the whole simulation along random directions.
static void check_gradient_through_steps(dpgen::FlowOptions options, int nx, int ny, int steps,
                                  unsigned seed0) {
  options.pressure_tolerance = 1e-13;
  dpgen::Flow2d flow(nx, ny, 1.0, blob(nx, ny, 4, 2, 1.5, 0.3), options);
  const VectorXd force = random_vector(2 * flow.cells(), seed0 + 7, -0.2, 0.2);
  flow.set_force(force);
  const VectorXd s0 = initial_state(flow, seed0 + 2);
  const Loss loss{flow, random_vector(flow.cells(), seed0 + 3, 0.0, 1.0)};

  // Gradient w.r.t. the whole initial state, the inflow and the force.
  VectorXd inflow_adj, force_adj;
  const auto gradient = [&](const dpgen::CheckpointOptions& cp) {
    inflow_adj = VectorXd::Zero(flow.cells());
    force_adj = VectorXd::Zero(2 * flow.cells());
    return dpgen::unrolled_gradient(
        s0, steps, [&](int, const VectorXd& s, VectorXd& next) { flow.step(s, next); },
        [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
          flow.step_adjoint(s, next_adj, s_adj, inflow_adj, force_adj);
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
  const VectorXd inflow_grad = inflow_adj, force_grad = force_adj;
  CHECK(g.stats.max_snapshots <= 2);
  CHECK(g.stats.recomputed_steps > 0);
  const dpgen::UnrolledGradient full = gradient({});
  CHECK(full.loss == g.loss);
  CHECK(full.state_adjoint == g.state_adjoint); // bit for bit: deterministic recomputation
  CHECK(inflow_adj == inflow_grad);
  CHECK(force_adj == force_grad);
  CHECK(force_grad.norm() > 0.0);

  // On a periodic axis the copy faces are never read: their gradient is exactly zero, while
  // the faces they copy (a boundary between two cells there) have a gradient like any other.
  double copy_grad = 0.0, first_grad = 0.0;
  for (int j = 0; j < ny && options.periodic_x; ++j) {
    copy_grad += std::abs(flow.u(g.state_adjoint)[j * (nx + 1) + nx]);
    first_grad += std::abs(flow.u(g.state_adjoint)[j * (nx + 1)]);
  }
  for (int i = 0; i < nx && options.periodic_y; ++i) {
    copy_grad += std::abs(flow.v(g.state_adjoint)[ny * nx + i]);
    first_grad += std::abs(flow.v(g.state_adjoint)[i]);
  }
  CHECK(copy_grad == 0.0);
  if (options.periodic_x || options.periodic_y)
    CHECK(first_grad > 0.0);

  // The loss of the whole simulation from an initial state, an inflow and a force.
  const auto simulate = [&](const VectorXd& s_init, const VectorXd& inflow, const VectorXd& f) {
    dpgen::Flow2d sim(nx, ny, 1.0, inflow, options);
    sim.set_force(f);
    VectorXd s = s_init, next;
    for (int t = 0; t < steps; ++t) {
      sim.step(s, next);
      s = next;
    }
    return loss.value(s);
  };
  CHECK(simulate(s0, flow.inflow(), force) == doctest::Approx(g.loss).epsilon(1e-14));

  // Directional derivatives along random directions: initial velocity only (wall faces stay
  // shut), initial marker only, inflow, force. Central differences with step 1e-7: the
  // semi-Lagrangian traces move by ~1e-7 cells, too little to cross a cell line in these seeds,
  // so the error is the truncation O(eps^2) plus rounding O(1e-16 L / eps). (With 1e-6 one
  // inflow direction of the MacCormack run crosses a kink of its limiter, min/max of the 4
  // cells, at a distance between 1e-7 and 1e-6: the one-sided differences there differ by 0.3%,
  // the adjoint agrees with the side the point is on.)
  const auto directional = [&](const VectorXd& d_state, const VectorXd& d_inflow,
                               const VectorXd& d_force) {
    const double eps = 1e-7;
    return (simulate(s0 + eps * d_state, flow.inflow() + eps * d_inflow, force + eps * d_force) -
            simulate(s0 - eps * d_state, flow.inflow() - eps * d_inflow, force - eps * d_force)) /
           (2 * eps);
  };
  const VectorXd zero_state = VectorXd::Zero(flow.state_size());
  const VectorXd zero_inflow = VectorXd::Zero(flow.cells());
  const VectorXd zero_force = VectorXd::Zero(2 * flow.cells());
  for (unsigned seed : {seed0 + 10u, seed0 + 20u, seed0 + 30u}) {
    CAPTURE(seed);
    VectorXd d_velocity = initial_state(flow, seed);
    flow.marker(d_velocity).setZero();
    const double fd_velocity = directional(d_velocity, zero_inflow, zero_force);
    CHECK(g.state_adjoint.dot(d_velocity) == doctest::Approx(fd_velocity).epsilon(1e-6));

    VectorXd d_marker = VectorXd::Zero(flow.state_size());
    flow.marker(d_marker) = random_vector(flow.cells(), seed + 1);
    CHECK(g.state_adjoint.dot(d_marker) ==
          doctest::Approx(directional(d_marker, zero_inflow, zero_force)).epsilon(1e-6));

    const VectorXd d_inflow = random_vector(flow.cells(), seed + 2);
    CHECK(inflow_grad.dot(d_inflow) ==
          doctest::Approx(directional(zero_state, d_inflow, zero_force)).epsilon(1e-6));

    const VectorXd d_force = random_vector(2 * flow.cells(), seed + 3);
    const double fd_force = directional(zero_state, zero_inflow, d_force);
    CHECK(std::abs(fd_force) > 1e-3); // the force matters: not a vacuous comparison
    CHECK(force_grad.dot(d_force) == doctest::Approx(fd_force).epsilon(1e-6));
  }
}

TEST_CASE("gradient through T flow steps with Revolve matches central differences and the full "
          "tape") {
  for (auto advection :
       {dpgen::MarkerAdvection::semi_lagrangian, dpgen::MarkerAdvection::maccormack})
    for (auto tangent : {dpgen::WallTangent::clamped, dpgen::WallTangent::zero}) {
      CAPTURE(static_cast<int>(advection));
      CAPTURE(static_cast<int>(tangent));
      dpgen::FlowOptions options;
      options.marker_advection = advection;
      options.wall_tangent = tangent;
      check_gradient_through_steps(options, 8, 10, 6, 0);
    }
}

TEST_CASE("closed walls: zero tangential ghosts change the velocity transport near the walls "
          "only") {
  // Same state, both settings: the advected velocity differs (traces end near the walls), and
  // a state at rest stays at rest.
  const int nx = 8, ny = 10;
  dpgen::FlowOptions clamped, zero;
  zero.wall_tangent = dpgen::WallTangent::zero;
  const Eigen::VectorXd inflow = Eigen::VectorXd::Zero(nx * ny);
  dpgen::Flow2d a(nx, ny, 1.0, inflow, clamped), b(nx, ny, 1.0, inflow, zero);
  const Eigen::VectorXd s0 = initial_state(a, 7);
  Eigen::VectorXd na, nb;
  a.step(s0, na);
  b.step(s0, nb);
  CHECK((a.u(na) - b.u(nb)).norm() > 1e-3);
  CHECK(a.marker(na) == b.marker(nb)); // the marker is transported by the old velocity
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(a.state_size());
  b.step(rest, nb);
  CHECK(nb.norm() == 0.0);
}

TEST_CASE("periodic flow: gradient through T steps (initial state, inflow, force) matches central "
          "differences") {
  // (periodic x, periodic y): x only, y only, both; traces of up to ~0.6 cells per step over 6
  // steps on 8x10 cells cross the periodic edges.
  for (auto [px, py] : {std::pair{true, false}, std::pair{false, true}, std::pair{true, true}})
    for (auto advection :
         {dpgen::MarkerAdvection::semi_lagrangian, dpgen::MarkerAdvection::maccormack}) {
      CAPTURE(px);
      CAPTURE(py);
      CAPTURE(static_cast<int>(advection));
      dpgen::FlowOptions options;
      options.marker_advection = advection;
      options.periodic_x = px;
      options.periodic_y = py;
      check_gradient_through_steps(options, 8, 10, 6, 100);
    }
}

TEST_CASE("periodic flow step: divergence-free, copy faces, shift equivariance") {
  const int nx = 16, ny = 12;
  for (auto [px, py] : {std::pair{true, false}, std::pair{false, true}, std::pair{true, true}}) {
    CAPTURE(px);
    CAPTURE(py);
    dpgen::FlowOptions options;
    options.periodic_x = px;
    options.periodic_y = py;
    options.marker_advection = dpgen::MarkerAdvection::maccormack;
    dpgen::Flow2d flow(nx, ny, 1.0, blob(nx, ny, 3, 2, 2, 0.3), options);
    flow.set_force(random_vector(2 * flow.cells(), 5, -0.1, 0.1));
    VectorXd state = initial_state(flow, 4), next;
    for (int t = 0; t < 4; ++t) {
      flow.step(state, next);
      state = next;
      CHECK(flow.forward_pressure_summary().iterations <= 15);
    }
    CHECK(flow.divergence(state).cwiseAbs().maxCoeff() < 1e-8);
    for (int j = 0; j < ny; ++j) {
      if (px) // the copy is bit-identical
        CHECK(flow.u(state)[j * (nx + 1) + nx] == flow.u(state)[j * (nx + 1)]);
      else
        CHECK((flow.u(state)[j * (nx + 1)] == 0.0 && flow.u(state)[j * (nx + 1) + nx] == 0.0));
    }
    for (int i = 0; i < nx; ++i) {
      if (py)
        CHECK(flow.v(state)[ny * nx + i] == flow.v(state)[i]);
      else
        CHECK((flow.v(state)[i] == 0.0 && flow.v(state)[ny * nx + i] == 0.0));
    }
    // A state's copy faces have no influence on the step.
    VectorXd other = state, next_other;
    for (int j = 0; j < ny && px; ++j)
      flow.u(other)[j * (nx + 1) + nx] += 0.3;
    for (int i = 0; i < nx && py; ++i)
      flow.v(other)[ny * nx + i] -= 0.3;
    flow.step(state, next);
    flow.step(other, next_other);
    CHECK(next_other == next);
  }

  // Fully periodic: moving everything (state, inflow, force) by (5, 7) cells moves the step's
  // result by as much. Walls, clamps or a wrong wrap anywhere break this.
  dpgen::FlowOptions options;
  options.periodic_x = options.periodic_y = true;
  options.marker_advection = dpgen::MarkerAdvection::maccormack;
  options.pressure_tolerance = 1e-12;
  const VectorXd inflow = blob(nx, ny, 3, 2, 2, 0.3);
  const VectorXd force = random_vector(2 * nx * ny, 6, -0.1, 0.1);
  dpgen::Flow2d flow(nx, ny, 1.0, inflow, options);
  dpgen::Flow2d moved(nx, ny, 1.0, shifted_cells(nx, ny, inflow, 5, 7), options);
  flow.set_force(force);
  moved.set_force(shifted_cells(nx, ny, force, 5, 7));
  VectorXd a = initial_state(flow, 8), b = shifted(flow, a, 5, 7), next;
  for (int t = 0; t < 3; ++t) {
    flow.step(a, next);
    a = next;
    moved.step(b, next);
    b = next;
  }
  CHECK((shifted(flow, a, 5, 7) - b).cwiseAbs().maxCoeff() < 1e-9);
  CHECK(a.cwiseAbs().maxCoeff() > 0.1);
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
