// The inverse heat problem of the Physics-based Deep Learning book's "Learning to Invert Heat
// Conduction with Scale-invariant Updates" (physgrad-code.ipynb), reduced to one dimension and
// without the network: recover x* (hot boxes) from y* = P(x*), P = diffusion by nu t = 8
// (32 explicit steps of the generated diffuse_explicit kernel, periodic), minimising
// |P(x) - y*|^2 by GD and Adam on the adjoint gradient, and by physical gradients (PG): a
// Newton step in y, then diffusion run backward with Tikhonov regularization (CG on
// (P^T P + lambda I) d = P^T r with the generated adjoint).
#include "common/cli.hpp"
#include "common/plot.hpp"
#include "common/report.hpp"

#include "diffuse_explicit_adjoint.hpp"
#include "dpgen/jacobian.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/physgrad.hpp"
#include "example_kernels.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;

// nu t = 8 as the notebook, on unit cells: 32 steps of dt nu = 0.25 (stable: <= 0.5).
constexpr int kSteps = 32;
constexpr double kDt = 0.25, kNu = 1.0, kDx = 1.0;

struct Heat {
  int n;
  // y = P x.
  VectorXd forward(const VectorXd& x) const {
    VectorXd u = x, next(n);
    for (int s = 0; s < kSteps; ++s) {
      diffuse_explicit(u.data(), next.data(), n, kDt, kNu, kDx);
      u.swap(next);
    }
    return u;
  }
  // P^T w: the generated adjoint, steps in reverse (P is linear: the adjoint reads no state).
  VectorXd adjoint(const VectorXd& w) const {
    VectorXd g = w, prev(n);
    for (int s = 0; s < kSteps; ++s) {
      prev.setZero();
      diffuse_explicit_adjoint(g.data(), prev.data(), g.data(), n, kDt, kNu, kDx);
      g.swap(prev);
    }
    return g;
  }
};

// The notebook's data, in 1D: 4 to 10 boxes of random centre, half width up to 10 cells and
// strength up to 1, added up.
VectorXd hot_boxes(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  const auto uniform = [&]() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  VectorXd x = VectorXd::Zero(n);
  const int count = 4 + static_cast<int>(7 * uniform());
  for (int b = 0; b < count; ++b) {
    const double half = 1.0 + 9.0 * uniform(), strength = uniform();
    const double centre = half + (n - 2 * half) * uniform();
    for (int i = 0; i < n; ++i)
      if (std::abs(i + 0.5 - centre) <= half)
        x[i] += strength;
  }
  return x;
}

} // namespace

int main(int argc, char** argv) try {
  dpgen_examples::Args args(argc, argv, "pg_heat",
                            "GD, Adam and PG (regularized inverse diffusion) on the inverse heat problem");
  const int n = args.get_int("--cells", 64, "cells (the notebook's grid is 64 x 64)", 8, 1 << 16);
  const int iters = args.get_int("--iters", 50, "updates per method (the notebook's STEPS)", 0);
  const double lr_gd = args.get_double("--lr-gd", 0.5, "GD step size (stable below 1)", 0, 1e9, true);
  const double lr_adam = args.get_double("--lr-adam", 0.05, "Adam step size", 0, 1e9, true);
  const double lambda = args.get_double(
      "--lambda", 1e-4, "Tikhonov weight of PG's inverse diffusion", 0, 1e9, true);
  const int seed = args.get_int("--seed", 1, "seed of the hot boxes", 0);
  // --require-reduction applies to PG; --check-gradient also checks dP/dx.
  const auto common = dpgen_examples::common_options(args, "pg_heat", false);
  if (args.finish())
    return 0;

  const Heat heat{n};
  const VectorXd x_true = hot_boxes(n, static_cast<unsigned>(seed));
  const VectorXd y_target = heat.forward(x_true);
  const auto loss_and_gradient = [&](const VectorXd& x, VectorXd& grad) {
    const VectorXd r = heat.forward(x) - y_target;
    grad = heat.adjoint(2.0 * r); // dL/dx = P^T 2 (P x - y*)
    return r.squaredNorm();
  };

  if (common.check) {
    const VectorXd at = hot_boxes(n, 99);
    // P is linear: its JVP is P v and its VJP P^T w, at any x.
    const auto jvp = [&](const VectorXd&, const VectorXd& v) { return heat.forward(v); };
    const auto vjp = [&](const VectorXd&, const VectorXd& w) { return heat.adjoint(w); };
    const Eigen::MatrixXd rows = dpgen::jacobian_by_rows(vjp, at, n);
    const Eigen::MatrixXd columns = dpgen::jacobian_by_columns(jvp, at, n);
    const double e_modes = (rows - columns).cwiseAbs().maxCoeff();
    const double e_fd = (rows - dpgen::jacobian_central_difference(
                                    [&](const VectorXd& x) { return heat.forward(x); }, at))
                            .cwiseAbs()
                            .maxCoeff();
    std::printf("dP/dx: rows (adjoint) vs columns (forward) %.2e, vs central differences %.2e\n",
                e_modes, e_fd);
    const int status =
        dpgen_examples::report_gradient_check(dpgen_examples::gradient_check(loss_and_gradient, at));
    return status == 0 && e_modes < 1e-13 && e_fd < 1e-8 ? 0 : 1;
  }

  struct Curve {
    std::string name, color;
    std::vector<double> iter, loss, x_error;
    double seconds = 0;
  };
  std::vector<Curve> curves;
  const auto run = [&](Curve c, auto&& update) {
    VectorXd x = VectorXd::Zero(n), grad;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k <= iters; ++k) {
      const double l = loss_and_gradient(x, grad);
      c.iter.push_back(k);
      c.loss.push_back(l);
      c.x_error.push_back((x - x_true).squaredNorm());
      if (k < 5 || k == iters)
        std::printf("%s iter %3d  L2 loss x ; y: %.6g ; %.6g\n", c.name.c_str(), k,
                    c.x_error.back(), l);
      if (k < iters)
        update(x, l, grad);
    }
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s: y loss %.4e -> %.4e, x error %.4e -> %.4e, %.3g s\n\n", c.name.c_str(),
                c.loss.front(), c.loss.back(), c.x_error.front(), c.x_error.back(), c.seconds);
    curves.push_back(std::move(c));
  };

  run({"GD", "#1f77b4", {}, {}, {}}, [&](VectorXd& x, double, const VectorXd& g) { x -= lr_gd * g; });
  dpgen::Adam adam(dpgen::AdamOptions{lr_adam});
  run({"Adam", "#2ca02c", {}, {}, {}}, [&](VectorXd& x, double l, VectorXd g) {
    adam.step(x, l, g, loss_and_gradient);
  });
  dpgen::PhysicalGradientProblem pg;
  pg.forward = [&](const VectorXd& x) { return heat.forward(x); };
  pg.loss = dpgen::l2_loss_newton(y_target);
  int cg_iterations = 0;
  pg.inverse = [&](const VectorXd& y_new, const VectorXd& x) {
    dpgen::CgSummary s;
    const VectorXd r = dpgen::regularized_inverse(
        [&](const VectorXd& v, VectorXd& o) { o = heat.forward(v); },
        [&](const VectorXd& w, VectorXd& o) { o = heat.adjoint(w); }, y_new, x, lambda, {}, &s);
    cg_iterations += s.iterations;
    return r;
  };
  run({"PG", "#d62728", {}, {}, {}}, [&](VectorXd& x, double, const VectorXd&) {
    x = dpgen::physical_update(pg, x); // lr 1: aim at y* in one Newton step
  });
  std::printf("PG: %d CG iterations in all (each applies P and P^T once)\n", cg_iterations);

  const std::string dir = dpgen_examples::output_dir(common.out);
  dpgen_examples::CsvLog csv(dir + "losses.csv", "method,iter,loss_y,error_x");
  std::vector<dpgen_examples::Series> ys, xs;
  for (const Curve& c : curves) {
    for (std::size_t k = 0; k < c.iter.size(); ++k)
      csv.line(c.name + ',' + std::to_string(k) + ',' + dpgen_examples::number(c.loss[k]) + ',' +
               dpgen_examples::number(c.x_error[k]));
    ys.push_back({c.name, c.iter, c.loss, c.color});
    xs.push_back({c.name, c.iter, c.x_error, c.color});
  }
  csv.close();
  dpgen_examples::write_svg_plot(dir + "loss_y.svg", "inverse heat: |P(x) - y*|^2", "iteration",
                                 "loss in y", ys, true);
  dpgen_examples::write_svg_plot(dir + "error_x.svg", "inverse heat: |x - x*|^2", "iteration",
                                 "error in x", xs, true);
  std::printf("wrote %slosses.csv %sloss_y.svg %serror_x.svg\n", dir.c_str(), dir.c_str(),
              dir.c_str());
  const Curve& p = curves.back();
  return dpgen_examples::check_reduction(p.loss.front() / p.loss.back(), common.require);
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
