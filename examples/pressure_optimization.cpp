// PhiFlow's "differentiate pressure" demo, as the seed text describes it: a 2D
// velocity field whose left half is optimized so that, after a pressure
// projection (divergence, a CG Poisson solve, subtracting the pressure
// gradient), its right half matches a target. The Poisson solve is
// differentiated by the implicit-function rule: one more CG solve in the
// backward pass, nothing of the forward iterations kept. Divergence, Poisson
// operator and gradient are dpgen kernels with generated adjoints.
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "dpgen/implicit_solve.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"
#include "example_kernels.hpp"
#include "mac_divergence_periodic_adjoint.hpp"
#include "mac_subtract_gradient_adjoint.hpp"
#include "neg_laplacian_periodic_adjoint.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <vector>

namespace {

using Eigen::VectorXd;

// Periodic MAC grid: u[k], v[k] on the west and south faces of cell k.
struct Grid {
  int nx, ny;
  double h;
  int cells() const { return nx * ny; }
  bool left(int k) const { return k % nx < nx / 2; } // the faces being optimized
};

// The projection P(u, v) = (u, v) - grad p with -laplace p = -div(u, v), and
// what its backward pass needs (the pressure, for the warm start of the next
// solve).
struct Projection {
  const Grid& g;
  dpgen::CgOptions cg;
  VectorXd pressure, lambda; // last solutions, warm starts
  dpgen::CgSummary forward_summary, backward_summary;
  dpgen::CgWorkspace workspace; // CG's vectors, reused by every forward and backward solve

  void apply_a(const VectorXd& x, VectorXd& y) const {
    neg_laplacian_periodic(x.data(), y.data(), g.nx, g.ny, g.h);
  }

  void forward(const VectorXd& u, const VectorXd& v, VectorXd& u_out, VectorXd& v_out) {
    const int n = g.cells();
    VectorXd div(n);
    mac_divergence_periodic(u.data(), v.data(), div.data(), g.nx, g.ny, g.h);
    VectorXd b = -div; // -laplace p = -div u
    auto a = [&](const VectorXd& x, VectorXd& y) { apply_a(x, y); };
    auto r = dpgen::solve_forward(a, b, cg, pressure.size() ? &pressure : nullptr);
    pressure = r.solution;
    forward_summary = r.summary;
    u_out.resize(n);
    v_out.resize(n);
    mac_subtract_gradient(u.data(), v.data(), pressure.data(), u_out.data(), v_out.data(), g.nx,
                          g.ny, g.h);
  }

  // Given the adjoints of the projected field, adds the adjoints of (u, v).
  void backward(const VectorXd& u, const VectorXd& v, const VectorXd& u_out_adj,
                const VectorXd& v_out_adj, VectorXd& u_adj, VectorXd& v_adj) {
    const int n = g.cells();
    VectorXd p_adj = VectorXd::Zero(n);
    // (u, v, p) -> (u - dp/dx, v - dp/dy): generated adjoint.
    mac_subtract_gradient_adjoint(u.data(), u_adj.data(), v.data(), v_adj.data(), pressure.data(),
                                  p_adj.data(), u_out_adj.data(), v_out_adj.data(), g.nx, g.ny,
                                  g.h);
    // p = A^-1 b: b_adj = A^-T p_adj, one CG solve (A symmetric); A has no
    // parameters here, so theta_bar is empty.
    auto a = [&](const VectorXd& x, VectorXd& y) { apply_a(x, y); };
    auto r = dpgen::solve_backward(a, p_adj, cg, lambda.size() ? &lambda : nullptr);
    lambda = r.solution;
    backward_summary = r.summary;
    // b = -div(u, v): div_adj = -b_adj, then the generated divergence adjoint.
    VectorXd div_adj = -lambda;
    mac_divergence_periodic_adjoint(u.data(), u_adj.data(), v.data(), v_adj.data(),
                                    div_adj.data(), g.nx, g.ny, g.h);
  }
};

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(
      argc, argv, "pressure_optimization",
      "Optimize the left half of a 2D velocity field so that after a pressure projection its\n"
      "right half matches a target (dpgen).\n\n"
      "Fixed setup: periodic MAC grid on [0, 1)^2, h = 1/nx; the target is the projection of\n"
      "a Gaussian jet (centre (0.4, 0.5), widths 0.06 x 0.2) in the left half; first guess 0;\n"
      "loss: squared error of the projected field over the right half; CG with the mean\n"
      "removed (periodic Poisson), absolute tolerance 1e-14, at most 20 nx ny iterations.");
  const int nx = args.get_int("--nx", 32, "cells in x (periodic, even)", 4);
  const int ny = args.get_int("--ny", 32, "cells in y (periodic)", 4);
  const int iters = args.get_int("--iters", 60, "optimizer iterations", 0);
  const std::string method = args.get_string("--optimizer", "gd", "gd, adam or lbfgs");
  const double lr = args.get_double("--lr", 0.4, "learning rate (gd, adam)", 0,
                                    std::numeric_limits<double>::infinity(), true);
  const double tol = args.get_double("--cg-tol", 1e-10, "relative CG tolerance, both solves", 0,
                                     1, true);
  const auto common = dpgen_examples::common_options(args, "pressure_optimization");
  if (args.finish())
    return 0;
  if (nx % 2)
    args.fail("--nx must be even (the left half is optimized), got " + std::to_string(nx));

  const Grid g{nx, ny, 1.0 / nx};
  const int n = g.cells();
  Projection proj{g, {}, {}, {}, {}, {}, {}};
  proj.cg.relative_tolerance = tol;
  proj.cg.absolute_tolerance = 1e-14;
  proj.cg.max_iterations = 20 * n;
  proj.cg.remove_null_space_mean = true; // periodic Poisson: constants are its null space
  proj.cg.name = "pressure solve";
  proj.cg.workspace = &proj.workspace;

  // The target: project a field that has a jet in the left half only; its
  // right half after projection (the flow the jet induces) is what the
  // optimization must reproduce from the left half alone.
  VectorXd u_star = VectorXd::Zero(n), v_star = VectorXd::Zero(n);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double x = (i + 0.5) / nx, y = (j + 0.5) / ny;
      if (!g.left(j * nx + i))
        continue; // reachable: the jet lives where the optimization acts
      double bump = std::exp(-(std::pow((x - 0.4) / 0.06, 2) + std::pow((y - 0.5) / 0.2, 2)));
      v_star[j * nx + i] = bump;                                         // upward jet
      u_star[j * nx + i] = 0.5 * bump * std::sin(6.283185307179586 * y); // with a sway
    }
  VectorXd u_target, v_target;
  proj.forward(u_star, v_star, u_target, v_target);

  // The optimized variables: u and v on the left faces; the right half of the
  // input field stays zero.
  std::vector<int> left;
  for (int k = 0; k < n; ++k)
    if (g.left(k))
      left.push_back(k);
  const int m = static_cast<int>(left.size());
  auto unpack = [&](const VectorXd& x, VectorXd& u, VectorXd& v) {
    u = VectorXd::Zero(n), v = VectorXd::Zero(n);
    for (int q = 0; q < m; ++q)
      u[left[q]] = x[q], v[left[q]] = x[m + q];
  };

  // L = sum over the right half of |P(u, v) - target|^2.
  VectorXd u_proj, v_proj;
  auto loss_and_gradient = [&](const VectorXd& x, VectorXd& grad) {
    VectorXd u, v;
    unpack(x, u, v);
    proj.forward(u, v, u_proj, v_proj);
    VectorXd u_out_adj = VectorXd::Zero(n), v_out_adj = VectorXd::Zero(n);
    double loss = 0;
    for (int k = 0; k < n; ++k) {
      if (g.left(k))
        continue;
      double du = u_proj[k] - u_target[k], dv = v_proj[k] - v_target[k];
      loss += du * du + dv * dv;
      u_out_adj[k] = 2 * du, v_out_adj[k] = 2 * dv;
    }
    VectorXd u_adj = VectorXd::Zero(n), v_adj = VectorXd::Zero(n);
    proj.backward(u, v, u_out_adj, v_out_adj, u_adj, v_adj);
    grad.resize(2 * m);
    for (int q = 0; q < m; ++q)
      grad[q] = u_adj[left[q]], grad[m + q] = v_adj[left[q]];
    return loss;
  };

  auto optimizer = dpgen_examples::make_optimizer(method, lr, "pressure_optimization");

  VectorXd x = VectorXd::Zero(2 * m);
  if (common.check) {
    // The loss is quadratic in x, so central differences are exact for any
    // step: a large one keeps the CG tolerance out of the comparison.
    VectorXd x0 = VectorXd::LinSpaced(2 * m, -0.5, 0.5); // a generic point
    return dpgen_examples::report_gradient_check(
        dpgen_examples::gradient_check(loss_and_gradient, x0, 3, 0.1));
  }
  dpgen_examples::LossCurve curve;
  dpgen::TrainSummary s = dpgen::train(loss_and_gradient, *optimizer, x,
                                       dpgen_examples::train_options(iters, common.csv, curve));
  VectorXd grad;
  loss_and_gradient(x, grad); // the final projected field, for the pictures
  const double reduction = s.initial_loss / s.final_loss;
  std::printf("loss %.6e -> %.6e (%.0fx lower) in %d iterations, %.2f s; %s\n", s.initial_loss,
              s.final_loss, reduction, s.iterations, s.seconds, s.message.c_str());
  std::printf("last CG solves: forward %d iterations (residual %.2e), backward %d iterations "
              "(residual %.2e)\n",
              proj.forward_summary.iterations, proj.forward_summary.final_residual_norm,
              proj.backward_summary.iterations, proj.backward_summary.final_residual_norm);

  const std::string dir = dpgen_examples::output_dir(common.out);
  auto vec = [](const VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  VectorXd u_opt, v_opt;
  unpack(x, u_opt, v_opt);
  // Panels: optimized input | its projection | target projection (v, then u),
  // coloured on the scale of the right halves (what is matched); the target's
  // own jet saturates. The dashed line separates the optimized left half from
  // the matched right half.
  double right_max = 0;
  for (int k = 0; k < n; ++k)
    if (!g.left(k))
      right_max = std::max({right_max, std::abs(u_target[k]), std::abs(v_target[k])});
  for (const char* component : {"v", "u"}) {
    const bool is_v = component[0] == 'v';
    dpgen_examples::FieldFigure fig;
    fig.title = std::string(component) + " after " + std::to_string(s.iterations) +
                " iterations (left half optimized, right half matched)";
    fig.panel_titles = {"optimized input", "after projection", "target"};
    fig.x_lines = {0.5};
    fig.value_label = component;
    fig.magnitude = right_max;
    fig.cell_pixels = std::max(2, 192 / std::max(nx, ny));
    fig.y_max = double(ny) / nx;
    dpgen_examples::write_png_fields(
        dir + component + "_fields.png",
        is_v ? std::vector<std::vector<double>>{vec(v_opt), vec(v_proj), vec(v_target)}
             : std::vector<std::vector<double>>{vec(u_opt), vec(u_proj), vec(u_target)},
        nx, ny, fig);
  }
  dpgen_examples::write_svg_plot(dir + "loss.svg", "pressure_optimization: loss", "iteration",
                                 "right-half error", {{"loss", curve.iteration, curve.loss}}, true);
  std::printf("pictures: %sv_fields.png %su_fields.png (optimized input | after projection | "
              "target), %sloss.svg\n",
              dir.c_str(), dir.c_str(), dir.c_str());
  return dpgen_examples::check_reduction(reduction, common.require);
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
