// The Physics-based Deep Learning book's "Simple Example comparing Different Optimizers"
// (physgrad-comparison.ipynb): minimise L(y(x)) = |y|^2 with the mock physics
// y(x) = (x0, x1^2) from x = (3, 3), ten updates each of gradient descent, Newton's method
// and the physical gradient (inverse simulator y^-1 = (y0, sqrt(y1)) after a Newton step of
// L in y), as the notebook does; plus Adam and half-inverse gradients, which it does not run.
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "dpgen/jacobian.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/physgrad.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

VectorXd physics(const VectorXd& x) { return VectorXd((VectorXd(2) << x[0], x[1] * x[1]).finished()); }
// dy/dx v and (dy/dx)^T w, written out: dy/dx = diag(1, 2 x1).
VectorXd physics_jvp(const VectorXd& x, const VectorXd& v) {
  return VectorXd((VectorXd(2) << v[0], 2.0 * x[1] * v[1]).finished());
}
VectorXd physics_vjp(const VectorXd& x, const VectorXd& w) {
  return VectorXd((VectorXd(2) << w[0], 2.0 * x[1] * w[1]).finished());
}
// dy/dx from the JVP columns and VJP rows (jacobian() takes columns when both are given and
// the Jacobian is square).
MatrixXd physics_jacobian(const VectorXd& x) {
  return dpgen::jacobian(physics_jvp, physics_vjp, x, 2);
}
double loss_of_y(const VectorXd& y) { return y.squaredNorm(); }

// L(x) and dL/dx = (dy/dx)^T dL/dy, dL/dy = 2 y.
double loss_and_gradient(const VectorXd& x, VectorXd& grad) {
  const VectorXd y = physics(x);
  grad = physics_vjp(x, 2.0 * y);
  return loss_of_y(y);
}

struct Run {
  std::string name, color;
  double step_size;
  std::vector<VectorXd> xs; // xs[0] = start, xs[k] after k updates
};

// The first update's component along the diagonal towards the origin, as the notebook's
// one_len: (dx / |dx|) . (1, 1), for dx = x0 - x1 (larger is better, at most sqrt 2).
double diagonal_length(const Run& r) {
  const VectorXd d = r.xs[0] - r.xs[1];
  return d.normalized().sum();
}

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(argc, argv, "physgrad_comparison",
                            "GD, Newton, PG (and Adam, HIG) on the book's y = (x0, x1^2), L = |y|^2");
  const int iters = args.get_int("--iters", 10, "updates per method (the notebook's 10)", 0, 100000);
  const double lr_gd = args.get_double("--lr-gd", 0.01, "GD step size (the notebook's)", 0, 1e9, true);
  const double lr_newton =
      args.get_double("--lr-newton", 1.0 / 3.0, "Newton step size (the notebook's)", 0, 1e9, true);
  const double lr_pg = args.get_double("--lr-pg", 0.3, "PG step size in y (the notebook's)", 0, 1e9, true);
  const double lr_adam = args.get_double(
      "--lr-adam", 0.75, "Adam step size (not in the notebook; first step ~ GD's)", 0, 1e9, true);
  const double lr_hig = args.get_double(
      "--lr-hig", 0.11, "HIG step size (not in the notebook; first step ~ GD's)", 0, 1e9, true);
  const double notebook_match = args.get_double(
      "--require-notebook-match", 0,
      "exit with an error unless GD's, Newton's and PG's iterate 9 are within this relative "
      "difference (per component) of the notebook's printed ones (0: no check)",
      0);
  // --require-reduction applies to PG and HIG; --check-gradient also checks dy/dx.
  const auto common = dpgen_examples::common_options(args, "physgrad_comparison", false);
  if (args.finish())
    return 0;
  if (notebook_match > 0 && iters < 10)
    args.fail("--require-notebook-match needs --iters 10 or more (the notebook prints iterate 9)");

  VectorXd x0(2);
  x0 << 3.0, 3.0;
  if (common.check) {
    // The Jacobian from JVP columns and from VJP rows against central differences, then dL/dx.
    const VectorXd at = (VectorXd(2) << 1.3, -0.7).finished();
    const double jac_error = (physics_jacobian(at) - dpgen::jacobian_central_difference(physics, at))
                                 .cwiseAbs()
                                 .maxCoeff();
    std::printf("Jacobian dy/dx: largest difference to central differences %.2e\n", jac_error);
    const double grad_error = dpgen_examples::gradient_check(loss_and_gradient, at);
    const int status = dpgen_examples::report_gradient_check(grad_error);
    return jac_error <= 1e-8 ? status : 1;
  }

  std::vector<Run> runs;
  std::vector<double> seconds;
  const auto timed = [&](Run r, auto&& update) {
    const auto t0 = std::chrono::steady_clock::now();
    r.xs = {x0};
    VectorXd x = x0;
    for (int k = 0; k < iters; ++k) {
      update(x);
      r.xs.push_back(x);
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    runs.push_back(std::move(r));
  };

  // GD: x <- x - lr dL/dx.
  timed({"GD", "#1f77b4", lr_gd, {}}, [&](VectorXd& x) {
    VectorXd g;
    loss_and_gradient(x, g);
    x -= lr_gd * g;
  });
  // Newton: x <- x - lr H^-1 dL/dx; L = x0^2 + x1^4, H = diag(2, 12 x1^2).
  timed({"Newton", "#ff7f0e", lr_newton, {}}, [&](VectorXd& x) {
    VectorXd g;
    loss_and_gradient(x, g);
    const VectorXd h = (VectorXd(2) << 2.0, 12.0 * x[1] * x[1]).finished();
    x -= lr_newton * g.cwiseQuotient(h);
  });
  // PG: y' = y - lr (d2L/dy2)^-1 dL/dy, x' = y^-1(y').
  dpgen::PhysicalGradientProblem pg;
  pg.forward = physics;
  pg.inverse = [](const VectorXd& y, const VectorXd&) {
    return VectorXd((VectorXd(2) << y[0], std::sqrt(y[1])).finished());
  };
  pg.loss = dpgen::l2_loss_newton(VectorXd::Zero(2));
  dpgen::PgOptions pg_options;
  pg_options.learning_rate = lr_pg;
  timed({"PG", "#d62728", lr_pg, {}}, [&](VectorXd& x) { x = dpgen::physical_update(pg, x, pg_options); });
  // Adam on dL/dx (dpgen::Adam evaluates f after its update).
  dpgen::Adam adam(dpgen::AdamOptions{lr_adam});
  timed({"Adam", "#2ca02c", lr_adam, {}}, [&](VectorXd& x) {
    VectorXd g;
    double l = loss_and_gradient(x, g);
    adam.step(x, l, g, loss_and_gradient);
  });
  // HIG: the Jacobian of y w.r.t. x, its singular values to the power -1/2, applied to
  // dL/dy = 2 y (hig_update's r: any loss's gradient in y, not only a residual's).
  dpgen::HigOptions hig_options;
  hig_options.learning_rate = lr_hig;
  hig_options.truncation = 1e-10;
  timed({"HIG", "#9467bd", lr_hig, {}},
        [&](VectorXd& x) { x += dpgen::hig_update(physics_jacobian(x), 2.0 * physics(x), hig_options).step; });

  const std::string dir = dpgen_examples::output_dir(common.out);
  dpgen_examples::CsvLog csv(dir + "iterates.csv", "method,iter,x0,x1,loss");
  std::vector<dpgen_examples::Series> loss_series, path_series;
  for (std::size_t m = 0; m < runs.size(); ++m) {
    const Run& r = runs[m];
    dpgen_examples::Series ls{r.name, {}, {}, r.color}, ps{r.name, {}, {}, r.color};
    for (std::size_t k = 0; k < r.xs.size(); ++k) {
      const VectorXd& x = r.xs[k];
      const double l = loss_of_y(physics(x));
      csv.line(r.name + ',' + std::to_string(k) + ',' + dpgen_examples::number(x[0]) + ',' +
               dpgen_examples::number(x[1]) + ',' + dpgen_examples::number(l));
      ls.x.push_back(double(k));
      ls.y.push_back(l);
      ps.x.push_back(x[0]);
      ps.y.push_back(x[1]);
      if (k > 0)
        std::printf("%s iter %d: [%.8g %.8g]  loss %.6e\n", r.name.c_str(), int(k - 1), x[0], x[1], l);
    }
    std::printf("%s (step size %.4g): final distance to the origin %.4f, loss %.4e, first-step "
                "diagonal length %.6f, wall time %.3g s\n\n",
                r.name.c_str(), r.step_size, r.xs.back().norm(), loss_of_y(physics(r.xs.back())),
                iters > 0 ? diagonal_length(r) : 0.0, seconds[m]);
    loss_series.push_back(ls);
    path_series.push_back(ps);
  }
  dpgen_examples::write_svg_plot(dir + "loss.svg", "physgrad comparison: L = |y(x)|^2",
                                 "iteration", "loss", loss_series, true);
  dpgen_examples::write_svg_plot(dir + "trajectories.svg", "iterates in x (target: origin)", "x0",
                                 "x1", path_series);
  std::printf("wrote %siterates.csv %sloss.svg %strajectories.svg\n", dir.c_str(), dir.c_str(),
              dir.c_str());

  // The notebook's iterate 9 (its printout, float32) for the methods it runs.
  const struct {
    const char* name;
    double x0, x1;
  } notebook[] = {{"GD", 2.4512184, 0.96171147},
                  {"Newton", 0.05202458, 0.92383826},
                  {"PG", 0.08474258, 0.50421}};
  int mismatch = 0;
  for (const auto& nb : notebook)
    for (const Run& r : runs)
      if (notebook_match > 0 && r.name == nb.name) {
        const VectorXd& x = r.xs[10];
        if (!(std::abs(x[0] - nb.x0) <= notebook_match * std::abs(nb.x0) &&
              std::abs(x[1] - nb.x1) <= notebook_match * std::abs(nb.x1))) {
          std::fprintf(stderr,
                       "error: %s iterate 9 is [%.8g %.8g], the notebook's [%.8g %.8g]: more "
                       "than %g apart (relative)\n",
                       nb.name, x[0], x[1], nb.x0, nb.x1, notebook_match);
          mismatch = 1;
        }
      }
  if (mismatch)
    return 1;

  const double l0 = loss_of_y(physics(x0));
  for (const Run& r : runs)
    if ((r.name == "PG" || r.name == "HIG") &&
        dpgen_examples::check_reduction(l0 / loss_of_y(physics(r.xs.back())), common.require))
      return 1;
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
