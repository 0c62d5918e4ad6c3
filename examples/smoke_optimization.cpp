// The Physics-based Deep Learning book's Navier-Stokes optimization (diffphys-code-ns.ipynb):
// smoke rises from an inflow in a closed 32x40 box; for three inflow positions, find the initial
// velocity such that after 20 steps the smoke matches the plume of a fourth, centred inflow.
// Gradient descent through the whole simulation: MacCormack marker transport, semi-Lagrangian
// self-advection, buoyancy, and a pressure projection whose gradient comes from the implicit
// rule (one more MG-preconditioned CG solve per step), all kernels dpgen kernels
// (runtime/solvers/include/dpgen/solvers/flow2d.hpp); binomial checkpointing on request.
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "dpgen/checkpoint.hpp"
#include "dpgen/solvers/flow2d.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;

// The notebook's batch: inflow centres in domain units (the box is 32 x 40), the last one the
// reference. Radius 3, 1/3 of marker per cell inside and step.
const double kCentres[4][2] = {{12, 4}, {13, 6}, {14, 5}, {16, 5}};
constexpr double kRadius = 3.0;
constexpr double kInflowRate = 1.0 / 3.0;

// The losses the notebook prints (its stored outputs, PhiFlow in float32, loss = sum over the
// batch of 1/2 sum (s - s_ref)^2) at these optimization steps (the loss of the iterate before
// that step's update).
const int kBookSteps[] = {0, 1, 2, 9, 19, 29, 39, 49, 59, 69, 79};
const double kBookLoss[] = {298.286163, 291.454376, 276.057831, 233.706482,
                            232.652145, 178.186951, 176.523254, 169.360931,
                            167.578674, 175.005310, 169.943680};

// The inflow field. "centre": rate where the cell centre lies inside the circle, 0 elsewhere
// (the notebook's CenteredGrid(Sphere(...)): PhiFlow samples a geometry as a hard mask at the
// cell centres). "area": rate times the fraction of the cell inside (16x16 samples per cell).
VectorXd inflow_field(int nx, int ny, double h, double cx, double cy, bool area) {
  VectorXd f(nx * ny);
  const int sub = area ? 16 : 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int inside = 0;
      for (int b = 0; b < sub; ++b)
        for (int a = 0; a < sub; ++a) {
          const double x = (i + (a + 0.5) / sub) * h, y = (j + (b + 0.5) / sub) * h;
          inside += (x - cx) * (x - cx) + (y - cy) * (y - cy) <= kRadius * kRadius;
        }
      f[j * nx + i] = kInflowRate * inside / double(sub * sub);
    }
  return f;
}

std::vector<double> vec(const Eigen::Ref<const VectorXd>& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(argc, argv, "smoke_optimization",
                            "Optimize the initial velocities of three smoke plumes so that after "
                            "20 steps they match a fourth (the PBDL book's NS example, dpgen).");
  // --large 1: the same physical problem (box, inflows, end time 20) at 8x the resolution in
  // each direction and 5x the steps; every default below can still be overridden.
  const bool large = args.get_int("--large", 0,
                                  "1: the larger run, 256x320 cells, 100 steps of dt 0.2, Revolve "
                                  "with 10 snapshots, Adam (defaults below are for 0)") != 0;
  const int scale = args.get_int("--scale", large ? 8 : 1,
                                 "cells per domain unit (1: the book's 32x40)");
  const int steps = args.get_int("--steps", large ? 100 : 20, "simulation steps");
  const double dt = args.get_double("--dt", large ? 0.2 : 1.0, "time step");
  const int iters = args.get_int("--iters", large ? 10 : 80, "optimizer iterations");
  const double lr = args.get_double("--lr", large ? 1e-3 : 1e-3, "learning rate");
  const std::string method =
      args.get_string("--optimizer", large ? "adam" : "gd", "gd, adam or lbfgs");
  const std::string advection =
      args.get_string("--advection", "maccormack", "marker transport: maccormack or sl");
  const std::string inflow_mask =
      args.get_string("--inflow", large ? "area" : "centre",
                      "inflow disc on the grid: centre (cells whose centre is inside, as the "
                      "notebook's PhiFlow) or area (the fraction of each cell inside)");
  const std::string wall_tangent = args.get_string(
      "--wall-tangent", large ? "clamped" : "zero",
      "velocity transport at the walls: zero (tangential velocity 0 beyond them, as PhiFlow's "
      "extrapolation.ZERO) or clamped (the value of the last face row)");
  const int checkpoints = args.get_int("--checkpoints", large ? 10 : 0,
                                       "Revolve snapshots per simulation (0: store every state)");
  const int frame_every = args.get_int(
      "--frame-every", large ? 5 : 1,
      "with --out: a PNG of the optimized plumes every this many steps (frames/frame_<t>.png)");
  const double tol = args.get_double("--pressure-tol", 1e-8, "relative tolerance, pressure solves");
  const double book_match = args.get_double(
      "--require-book-match", 0,
      "exit with an error unless the losses at the steps up to 2 that ran are within this "
      "relative difference of the notebook's (the book's setup only; 0: no check)",
      0);
  const auto common = dpgen_examples::common_options(args, "smoke_optimization");
  if (args.finish())
    return 0;
  if (scale < 1 || steps < 1 || iters < 0 || !(dt > 0) || checkpoints < 0 || frame_every < 1)
    throw std::invalid_argument("smoke_optimization: need --scale >= 1, --steps >= 1, --dt > 0, "
                                "--iters >= 0, --checkpoints >= 0, --frame-every >= 1");
  const bool book_setup = scale == 1 && steps == 20 && dt == 1.0;
  if (book_match > 0 && !book_setup)
    throw std::invalid_argument("smoke_optimization: --require-book-match needs the book's "
                                "setup (--scale 1 --steps 20 --dt 1)");
  if (advection != "maccormack" && advection != "sl")
    throw std::invalid_argument("smoke_optimization: --advection must be maccormack or sl, got '" +
                                advection + "'");
  if (inflow_mask != "centre" && inflow_mask != "area")
    throw std::invalid_argument("smoke_optimization: --inflow must be centre or area, got '" +
                                inflow_mask + "'");
  if (wall_tangent != "zero" && wall_tangent != "clamped")
    throw std::invalid_argument(
        "smoke_optimization: --wall-tangent must be zero or clamped, got '" + wall_tangent + "'");

  const int nx = 32 * scale, ny = 40 * scale;
  const double h = 1.0 / scale, area = h * h;
  dpgen::FlowOptions options;
  options.dt = dt;
  options.buoyancy = 1.0;
  options.pressure_tolerance = tol;
  options.marker_advection = advection == "sl" ? dpgen::MarkerAdvection::semi_lagrangian
                                               : dpgen::MarkerAdvection::maccormack;
  options.wall_tangent =
      wall_tangent == "zero" ? dpgen::WallTangent::zero : dpgen::WallTangent::clamped;
  std::vector<std::unique_ptr<dpgen::Flow2d>> flows;
  for (const auto& c : kCentres)
    flows.push_back(std::make_unique<dpgen::Flow2d>(
        nx, ny, h, inflow_field(nx, ny, h, c[0], c[1], inflow_mask == "area"), options));
  const dpgen::Flow2d& shape = *flows[0];
  const Eigen::Index velocity_size = shape.u_faces() + shape.v_faces();
  std::printf("smoke_optimization: %dx%d cells, %d steps of dt %g, %s marker transport, "
              "inflow mask '%s', tangential velocity at the walls '%s', %d velocity unknowns "
              "per plume\n",
              nx, ny, steps, dt, advection.c_str(), inflow_mask.c_str(), wall_tangent.c_str(),
              int(velocity_size));

  // A plume from an initial velocity (the marker starts empty): the marker at every step.
  const auto simulate = [&](dpgen::Flow2d& flow, const Eigen::Ref<const VectorXd>& velocity) {
    VectorXd state = VectorXd::Zero(flow.state_size()), next;
    state.tail(velocity_size) = velocity;
    std::vector<VectorXd> markers(1, state.head(flow.cells()));
    for (int t = 0; t < steps; ++t) {
      flow.step(state, next);
      state.swap(next);
      markers.push_back(state.head(flow.cells()));
    }
    return markers;
  };
  const VectorXd reference = simulate(*flows[3], VectorXd::Zero(velocity_size)).back();

  // x: the initial velocities [u, v] of the three plumes, one after the other. The wall faces
  // are no unknowns: the simulation multiplies them by 0 (so their gradient is 0 too).
  VectorXd wall_mask = VectorXd::Ones(velocity_size);
  for (int j = 0; j < ny; ++j)
    wall_mask[j * (nx + 1)] = wall_mask[j * (nx + 1) + nx] = 0.0;
  for (int i = 0; i < nx; ++i)
    wall_mask[shape.u_faces() + i] = wall_mask[shape.u_faces() + ny * nx + i] = 0.0;

  // L = sum over the plumes of 1/2 sum_cells (s_T - s_ref)^2 h^2 (PhiFlow's l2_loss, h = 1 in
  // the book's setup), and dL/dx through the T steps.
  dpgen::CheckpointOptions cp;
  if (checkpoints > 0) {
    cp.strategy = dpgen::CheckpointStrategy::revolve;
    cp.snapshots = checkpoints;
  }
  dpgen::CheckpointStats last_stats;
  dpgen::CheckpointWorkspace tape; // the states, kept from one gradient to the next
  const auto loss_and_gradient = [&](const VectorXd& x, VectorXd& grad) {
    grad.setZero(x.size());
    double total = 0.0;
    for (int b = 0; b < 3; ++b) {
      dpgen::Flow2d& flow = *flows[b];
      VectorXd s0 = VectorXd::Zero(flow.state_size());
      s0.tail(velocity_size) = x.segment(b * velocity_size, velocity_size).cwiseProduct(wall_mask);
      VectorXd inflow_adj = VectorXd::Zero(flow.cells()); // not optimized here
      const dpgen::UnrolledGradient g = dpgen::unrolled_gradient(
          s0, steps, [&](int, const VectorXd& s, VectorXd& next) { flow.step(s, next); },
          [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
            flow.step_adjoint(s, next_adj, s_adj, inflow_adj);
          },
          [&](int t, const VectorXd& s, VectorXd& adj) {
            if (t != steps)
              return 0.0;
            const VectorXd r = s.head(flow.cells()) - reference;
            adj.head(flow.cells()) += area * r;
            return 0.5 * area * r.squaredNorm();
          },
          cp, &tape);
      total += g.loss;
      grad.segment(b * velocity_size, velocity_size) =
          g.state_adjoint.tail(velocity_size).cwiseProduct(wall_mask);
      last_stats = g.stats;
    }
    return total;
  };

  VectorXd x = VectorXd::Zero(3 * velocity_size); // the book starts from rest
  if (common.check) {
    // A non-trivial point: small random velocities.
    VectorXd at = 0.05 * VectorXd::Random(x.size());
    for (int b = 0; b < 3; ++b)
      at.segment(b * velocity_size, velocity_size).array() *= wall_mask.array();
    return dpgen_examples::report_gradient_check(
        dpgen_examples::gradient_check(loss_and_gradient, at));
  }

  const auto optimizer = dpgen_examples::make_optimizer(method, lr, "smoke_optimization");
  dpgen_examples::LossCurve curve;
  const auto start = std::chrono::steady_clock::now();
  const dpgen::TrainSummary s = dpgen::train(
      loss_and_gradient, *optimizer, x, dpgen_examples::train_options(iters, common.csv, curve));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("loss %.6g -> %.6g (%.2fx lower) in %d iterations; %s\n", s.initial_loss,
              s.final_loss, s.initial_loss / s.final_loss, s.iterations, s.message.c_str());
  std::printf("wall time: %.3g s for %d loss+gradient evaluations (%.3g s each; 3 plumes x %d "
              "steps each, forward and backward); per plume: %lld forward steps, %d states "
              "stored at most\n",
              wall, s.evaluations, wall / std::max(1, s.evaluations), steps,
              last_stats.forward_steps, last_stats.max_snapshots);
  int book_mismatch = 0;
  if (book_setup) {
    // Every iteration, with the notebook's number where it prints one (steps 0, 1, 2, 9, 19,
    // ..., 79) and the relative difference.
    std::printf("\noptimization step | loss (dpgen) | loss (notebook, PhiFlow) | difference\n");
    size_t b = 0;
    for (size_t k = 0; k < curve.loss.size(); ++k) {
      while (b < std::size(kBookSteps) && size_t(kBookSteps[b]) < k)
        ++b;
      if (b < std::size(kBookSteps) && size_t(kBookSteps[b]) == k)
        std::printf("%17zu | %12.3f | %24.3f | %+9.2f%%\n", k, curve.loss[k], kBookLoss[b],
                    100.0 * (curve.loss[k] / kBookLoss[b] - 1.0));
      else
        std::printf("%17zu | %12.3f |\n", k, curve.loss[k]);
    }
    // Steps 0 to 2: later ones are not comparable one by one (GD at this rate oscillates, and a
    // relative change of 1e-8 in the pressure solves moves a loss at step 9 by 10%).
    for (size_t k = 0; book_match > 0 && k < 3 && k < curve.loss.size(); ++k)
      if (!(std::abs(curve.loss[k] / kBookLoss[k] - 1.0) <= book_match)) {
        std::fprintf(stderr, "error: loss at step %zu is %.6g, the notebook's %.6g: more than "
                     "%g apart (relative)\n", k, curve.loss[k], kBookLoss[k], book_match);
        book_mismatch = 1;
      }
    const size_t last = std::size(kBookSteps) - 1, at = size_t(kBookSteps[last]);
    if (at < curve.loss.size())
      std::printf("reduction by step %zu: dpgen %.1f%%, notebook %.1f%%\n", at,
                  100.0 * (1.0 - curve.loss[at] / curve.loss[0]),
                  100.0 * (1.0 - kBookLoss[last] / kBookLoss[0]));
  }

  // Pictures: the plumes at step T before (from rest) and after optimization, with the
  // reference; and the optimized first plume against the reference every T/5 steps.
  if (!common.out.empty()) {
    const std::string dir = dpgen_examples::output_dir(common.out);
    std::vector<std::vector<double>> before, after, frames;
    std::vector<std::vector<std::vector<double>>> runs;
    for (int b = 0; b < 3; ++b) {
      before.push_back(
          vec(simulate(*flows[b], VectorXd::Zero(velocity_size)).back()));
      runs.push_back({});
      for (const VectorXd& st : simulate(*flows[b], x.segment(b * velocity_size, velocity_size)))
        runs.back().push_back(vec(st));
      after.push_back(runs.back().back());
    }
    before.push_back(vec(reference));
    after.push_back(vec(reference));
    const auto ref_run = simulate(*flows[3], VectorXd::Zero(velocity_size));
    const double top = std::max(reference.maxCoeff(), 1e-12);
    // The marker as fields with axes, panel titles and a colour bar.
    auto figure = [&](const std::string& title, std::vector<std::string> panels) {
      dpgen_examples::FieldFigure fig;
      fig.title = title;
      fig.panel_titles = std::move(panels);
      fig.x_max = nx;
      fig.y_max = ny;
      fig.value_label = "marker";
      fig.magnitude = top;
      fig.cell_pixels = 4 / scale + 1;
      return fig;
    };
    const std::vector<std::string> finals = {"plume 1", "plume 2", "plume 3", "reference"};
    dpgen_examples::write_png_fields(
        dir + "final_before.png", before, nx, ny,
        figure("marker at step " + std::to_string(steps) + ", zero initial velocity", finals));
    dpgen_examples::write_png_fields(
        dir + "final_optimized.png", after, nx, ny,
        figure("marker at step " + std::to_string(steps) + ", optimized initial velocity",
               finals));
    std::vector<std::string> frame_titles;
    for (int k = 1; k <= 5; ++k) {
      frames.push_back(runs[0][size_t(k * steps / 5)]);
      frame_titles.push_back("ours, t=" + std::to_string(k * steps / 5));
    }
    for (int k = 1; k <= 5; ++k) {
      frames.push_back(vec(ref_run[size_t(k * steps / 5)]));
      frame_titles.push_back("ref., t=" + std::to_string(k * steps / 5));
    }
    dpgen_examples::write_png_fields(dir + "frames.png", frames, nx, ny,
                                     figure("optimized plume 1 against the reference",
                                            frame_titles));
    // The optimized plumes (and the reference) as PNG frames, one every frame_every steps and
    // the last one: frames/frame_<t>.png.
    const std::string frame_dir = dpgen_examples::output_dir(dir + "frames");
    int frame_count = 0;
    for (int t = 0; t <= steps; ++t) {
      if (t % frame_every != 0 && t != steps)
        continue;
      std::vector<std::vector<double>> panels;
      for (int b = 0; b < 3; ++b)
        panels.push_back(runs[size_t(b)][size_t(t)]);
      panels.push_back(vec(ref_run[size_t(t)]));
      char name[32];
      std::snprintf(name, sizeof name, "frame_%03d.png", t);
      dpgen_examples::write_png_fields(
          frame_dir + name, panels, nx, ny,
          figure("optimized plumes and the reference, step " + std::to_string(t) + " of " +
                     std::to_string(steps),
                 {"plume 1", "plume 2", "plume 3", "reference"}));
      ++frame_count;
    }
    std::vector<dpgen_examples::Series> series = {{"dpgen", curve.iteration, curve.loss}};
    if (book_setup) {
      dpgen_examples::Series book{"notebook (PhiFlow), printed steps", {}, {}, "#d62728", true};
      for (size_t b = 0; b < std::size(kBookSteps); ++b) {
        book.x.push_back(kBookSteps[b]);
        book.y.push_back(kBookLoss[b]);
      }
      series.push_back(book);
    }
    dpgen_examples::write_svg_plot(dir + "loss.svg", "smoke_optimization: loss", "iteration",
                                   "sum of 1/2 |s_T - s_ref|^2", series, true);
    std::printf("pictures: %sfinal_before.png %sfinal_optimized.png %sframes.png (strip) "
                "%sloss.svg, %d frames in %s\n",
                dir.c_str(), dir.c_str(), dir.c_str(), dir.c_str(), frame_count,
                frame_dir.c_str());
  }
  return std::max(book_mismatch,
                  dpgen_examples::check_reduction(s.initial_loss / s.final_loss, common.require));
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
