// Tests of dpgen/optim.hpp: gradient descent and Adam against their update formulas and on a
// quadratic; L-BFGS (stepwise and LBFGSSolver-driven) on a quadratic and on Rosenbrock;
// half-inverse gradients against Gauss-Newton and GD, truncation, and on an ill-conditioned
// least-squares problem.
#include "dpgen/optim.hpp"

#include "dpgen/jacobian.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using Eigen::VectorXd;

// f(x) = 1/2 x^T A x - b^T x with A = diag(1 .. n) + a rank-one coupling: SPD, cond ~ 2n.
struct Quadratic {
  int n = 10;
  Eigen::MatrixXd a;
  VectorXd b;
  Quadratic() {
    const VectorXd u = VectorXd::LinSpaced(n, -1.0, 1.0) / std::sqrt(double(n));
    a = Eigen::MatrixXd(VectorXd::LinSpaced(n, 1.0, double(n)).asDiagonal()) + u * u.transpose();
    b = VectorXd::LinSpaced(n, 0.5, -0.5);
  }
  double operator()(const VectorXd& x, VectorXd& grad) const {
    grad = a * x - b;
    return 0.5 * x.dot(a * x) - b.dot(x);
  }
  VectorXd minimizer() const { return a.ldlt().solve(b); }
  double largest_eigenvalue() const {
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues().maxCoeff();
  }
};

// Extended Rosenbrock: sum_i 100 (x_{2i+1} - x_{2i}^2)^2 + (1 - x_{2i})^2, minimum at 1.
double rosenbrock(const VectorXd& x, VectorXd& grad) {
  grad.setZero(x.size());
  double f = 0.0;
  for (Eigen::Index i = 0; i + 1 < x.size(); i += 2) {
    const double t1 = 1.0 - x[i], t2 = 10.0 * (x[i + 1] - x[i] * x[i]);
    grad[i + 1] = 20.0 * t2;
    grad[i] = -2.0 * (x[i] * grad[i + 1] + t1);
    f += t1 * t1 + t2 * t2;
  }
  return f;
}

VectorXd rosenbrock_start(Eigen::Index n) {
  VectorXd x(n);
  for (Eigen::Index i = 0; i < n; i += 2) {
    x[i] = -1.2;
    x[i + 1] = 1.0;
  }
  return x;
}

// Runs `iterations` optimizer steps from x0 and returns the final x.
VectorXd run(dpgen::Optimizer& optimizer, const dpgen::LossGradient& f, VectorXd x,
             int iterations) {
  VectorXd grad;
  double loss = f(x, grad);
  for (int k = 0; k < iterations; ++k)
    optimizer.step(x, loss, grad, f);
  return x;
}

// r(x) = A x - b with A = Q diag(sigma) W^T (Q, W orthonormal from QR of random matrices):
// a least-squares problem with prescribed singular values.
struct LinearResidual {
  Eigen::MatrixXd a;
  VectorXd b;
  LinearResidual(Eigen::Index m, const VectorXd& sigma, unsigned seed) {
    const Eigen::Index n = sigma.size();
    const auto random_matrix = [](Eigen::Index rows, Eigen::Index cols, unsigned s) {
      return Eigen::MatrixXd(dpgen_test::random_vector(rows * cols, s).reshaped(rows, cols));
    };
    const Eigen::MatrixXd q =
        Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix(m, n, seed)).householderQ() *
        Eigen::MatrixXd::Identity(m, n);
    const Eigen::MatrixXd w =
        Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix(n, n, seed + 1)).householderQ();
    a = q * sigma.asDiagonal() * w.transpose();
    b = dpgen_test::random_vector(m, seed + 2);
  }
  VectorXd operator()(const VectorXd& x, Eigen::MatrixXd& jac) const {
    jac = a;
    return a * x - b;
  }
  // L = 1/2 |A x - b|^2, grad = A^T (A x - b).
  double loss(const VectorXd& x, VectorXd& grad) const {
    const VectorXd r = a * x - b;
    grad = a.transpose() * r;
    return 0.5 * r.squaredNorm();
  }
  VectorXd minimizer() const { return a.colPivHouseholderQr().solve(b); }
};

dpgen::HigOptions hig_options(double learning_rate, double exponent, double truncation,
                              int max_iterations) {
  dpgen::HigOptions o;
  o.learning_rate = learning_rate;
  o.exponent = exponent;
  o.truncation = truncation;
  o.max_iterations = max_iterations;
  return o;
}

} // namespace

TEST_CASE("gradient descent: the update rule and convergence on a quadratic") {
  const Quadratic q;
  const VectorXd x0 = VectorXd::Ones(q.n);
  dpgen::GradientDescent gd({0.05});
  VectorXd x = x0, grad;
  double loss = q(x, grad);
  const VectorXd g0 = grad;
  CHECK(gd.step(x, loss, grad, q) == 1);
  CHECK(x == x0 - 0.05 * g0); // x1 = x0 - lr g0, exactly
  VectorXd grad_new;
  const double loss_new = q(x, grad_new);
  CHECK(loss == loss_new); // loss and grad describe the new iterate
  CHECK(grad == grad_new);

  // With lr = 1 / lambda_max the error contracts at least by (1 - lambda_min / lambda_max).
  dpgen::GradientDescent tuned({1.0 / q.largest_eigenvalue()});
  const VectorXd x_star = q.minimizer();
  CHECK((run(tuned, q, x0, 600) - x_star).norm() < 1e-10 * x_star.norm());
}

TEST_CASE("Adam: bias-corrected moments, checked against a direct transcription") {
  const Quadratic q;
  dpgen::AdamOptions o;
  o.learning_rate = 0.01;
  dpgen::Adam adam(o);
  VectorXd x = VectorXd::Ones(q.n), grad;
  double loss = q(x, grad);

  // Kingma & Ba, Algorithm 1, written out for three steps.
  VectorXd x_ref = x, m = VectorXd::Zero(q.n), v = VectorXd::Zero(q.n), g;
  q(x_ref, g);
  for (int t = 1; t <= 3; ++t) {
    m = 0.9 * m + 0.1 * g;
    v = 0.999 * v + 0.001 * g.cwiseProduct(g);
    const VectorXd m_hat = m / (1.0 - std::pow(0.9, t));
    const VectorXd v_hat = v / (1.0 - std::pow(0.999, t));
    x_ref -= (0.01 * m_hat.array() / (v_hat.array().sqrt() + 1e-8)).matrix();
    q(x_ref, g);
    adam.step(x, loss, grad, q);
    CHECK((x - x_ref).norm() <= 1e-15 * x_ref.norm());
  }
  // The first bias-corrected step moves every coordinate by about the learning rate.
  dpgen::Adam fresh(o);
  VectorXd y = VectorXd::Ones(q.n), gy;
  double ly = q(y, gy);
  fresh.step(y, ly, gy, q);
  CHECK(((VectorXd::Ones(q.n) - y).cwiseAbs().array() - 0.01).abs().maxCoeff() < 1e-8);

  // reset() forgets the moments: the next step equals a fresh optimizer's first step.
  adam.reset();
  VectorXd z = VectorXd::Ones(q.n), gz;
  double lz = q(z, gz);
  adam.step(z, lz, gz, q);
  CHECK(z == y);

  // Converges on the quadratic (constant learning rate: to within about the rate).
  dpgen::AdamOptions fast;
  fast.learning_rate = 0.05;
  dpgen::Adam adam_fast(fast);
  const VectorXd x_star = q.minimizer();
  CHECK((run(adam_fast, q, VectorXd::Ones(q.n), 3000) - x_star).norm() < 1e-3);
}

TEST_CASE("L-BFGS stepwise solves a quadratic in few iterations") {
  const Quadratic q;
  dpgen::Lbfgs lbfgs;
  VectorXd x = VectorXd::Ones(q.n), grad;
  double loss = q(x, grad);
  int iterations = 0;
  while (grad.norm() > 1e-10 && iterations < 50) {
    CHECK(lbfgs.step(x, loss, grad, q) >= 1);
    ++iterations;
  }
  CHECK(grad.norm() <= 1e-10);
  CHECK(iterations < 50);
  CHECK((x - q.minimizer()).norm() < 1e-9);

  // At an exact stationary point there is no direction to search: no evaluation, no move.
  const dpgen::LossGradient never = [](const VectorXd&, VectorXd&) -> double {
    FAIL("no evaluation expected at a zero gradient");
    return 0.0;
  };
  VectorXd at = x, zero = VectorXd::Zero(q.n);
  CHECK(dpgen::Lbfgs().step(at, loss, zero, never) == 0);
  CHECK(at == x);
}

TEST_CASE("L-BFGS on Rosenbrock: LBFGSSolver wrapper and stepwise iterates agree bit for bit") {
  dpgen::LbfgsOptions param;
  param.epsilon = 1e-10;
  param.epsilon_rel = 0.0;
  param.max_iterations = 500;
  VectorXd x = rosenbrock_start(10);
  const dpgen::LbfgsSummary summary = dpgen::lbfgs_minimize(rosenbrock, x, param);
  CHECK(summary.iterations > 10);
  CHECK((x - VectorXd::Ones(10)).norm() < 1e-8);
  CHECK(summary.final_grad_norm <= 1e-10);
  CHECK(summary.final_loss < 1e-16);
  CHECK(summary.termination == dpgen::Termination::gradient_tolerance);
  CHECK(summary.converged());
  CHECK(summary.message.rfind("lbfgs: gradient_tolerance after ", 0) == 0);

  dpgen::Lbfgs stepwise(param);
  const VectorXd y = run(stepwise, rosenbrock, rosenbrock_start(10), summary.iterations);
  CHECK(std::memcmp(x.data(), y.data(), sizeof(double) * 10) == 0);
}

TEST_CASE("optimizer errors") {
  CHECK_THROWS_WITH_AS(dpgen::GradientDescent({0.0}), "gd: learning rate must be positive (got 0)",
                       std::invalid_argument);
  dpgen::AdamOptions bad;
  bad.beta1 = 1.0;
  CHECK_THROWS_AS(dpgen::Adam{bad}, std::invalid_argument);

  // A gradient with the wrong sign makes -grad an ascent direction: no step decreases the loss.
  const dpgen::LossGradient wrong_sign = [](const VectorXd& x, VectorXd& grad) {
    grad = -x;
    return 0.5 * x.squaredNorm();
  };
  dpgen::Lbfgs lbfgs;
  VectorXd x = VectorXd::Ones(3), grad;
  double loss = wrong_sign(x, grad);
  CHECK_THROWS_WITH_AS(lbfgs.step(x, loss, grad, wrong_sign),
                       "lbfgs: line search failed in iteration 1: the line search routine "
                       "reached the maximum number of iterations",
                       dpgen::OptimizationError);
  VectorXd y = VectorXd::Ones(3);
  CHECK_THROWS_WITH_AS(dpgen::lbfgs_minimize(wrong_sign, y),
                       "lbfgs: the line search routine reached the maximum number of iterations",
                       dpgen::OptimizationError);
  dpgen::LbfgsOptions quiet;
  quiet.throw_on_failure = false;
  y = VectorXd::Ones(3);
  const dpgen::LbfgsSummary failed = dpgen::lbfgs_minimize(wrong_sign, y, quiet);
  CHECK(failed.termination == dpgen::Termination::line_search_failed);
  CHECK(failed.failed());
}

TEST_CASE("lbfgs_minimize: termination reasons (limit, gradient, loss decrease, NaN)") {
  dpgen::LbfgsOptions options;
  options.epsilon = 1e-10;
  options.epsilon_rel = 0.0;
  options.max_iterations = 5;
  VectorXd x = rosenbrock_start(6);
  const dpgen::LbfgsSummary limit = dpgen::lbfgs_minimize(rosenbrock, x, options);
  CHECK(limit.termination == dpgen::Termination::max_iterations);
  CHECK(limit.iterations == 5);
  CHECK_FALSE(limit.converged());
  CHECK(limit.message.rfind("lbfgs: max_iterations after 5 iterations", 0) == 0);
  VectorXd g;
  CHECK(limit.initial_loss == rosenbrock(rosenbrock_start(6), g));

  // Started at the minimizer: converged without a line search.
  VectorXd at = VectorXd::Ones(6);
  const dpgen::LbfgsSummary none = dpgen::lbfgs_minimize(rosenbrock, at, options);
  CHECK(none.termination == dpgen::Termination::gradient_tolerance);
  CHECK(none.iterations == 0);

  // The relative decrease over `past` iterations below delta.
  dpgen::LbfgsOptions stall = options;
  stall.epsilon = 0.0;
  stall.max_iterations = 0; // no limit
  stall.past = 1;
  stall.delta = 1e-3;
  const dpgen::LossGradient bowl = [](const VectorXd& v, VectorXd& grad) {
    const VectorXd w = VectorXd::LinSpaced(v.size(), 1.0, double(v.size()));
    grad = w.cwiseProduct(v - VectorXd::Ones(v.size()));
    return 1.0 + 0.5 * w.dot((v - VectorXd::Ones(v.size())).cwiseAbs2());
  };
  VectorXd y = VectorXd::Zero(6);
  const dpgen::LbfgsSummary decrease = dpgen::lbfgs_minimize(bowl, y, stall);
  CHECK(decrease.termination == dpgen::Termination::loss_decrease);
  CHECK(decrease.converged());

  // NaN at the start: loss_not_finite, thrown with the summary or returned.
  const dpgen::LossGradient nan_loss = [](const VectorXd& v, VectorXd& grad) {
    grad = v;
    return std::numeric_limits<double>::quiet_NaN();
  };
  VectorXd z = VectorXd::Ones(3);
  try {
    dpgen::lbfgs_minimize(nan_loss, z);
    FAIL("expected an OptimizationError");
  } catch (const dpgen::OptimizationError& e) {
    REQUIRE(e.has_summary());
    CHECK(e.summary().termination == dpgen::Termination::loss_not_finite);
    CHECK(std::string(e.what()) == "lbfgs: loss is NaN at the initial point");
  }
  dpgen::LbfgsOptions quiet;
  quiet.throw_on_failure = false;
  const dpgen::LbfgsSummary nan = dpgen::lbfgs_minimize(nan_loss, z, quiet);
  CHECK(nan.termination == dpgen::Termination::loss_not_finite);
  CHECK(nan.message == "lbfgs: loss is NaN at the initial point");
  CHECK(std::isnan(nan.final_loss));
  // A NaN gradient at a later evaluation.
  int calls = 0;
  const dpgen::LossGradient nan_gradient = [&](const VectorXd& v, VectorXd& grad) {
    const double loss = rosenbrock(v, grad);
    if (++calls == 3)
      grad[2] = std::numeric_limits<double>::quiet_NaN();
    return loss;
  };
  VectorXd w = rosenbrock_start(6);
  const dpgen::LbfgsSummary bad = dpgen::lbfgs_minimize(nan_gradient, w, quiet);
  CHECK(bad.termination == dpgen::Termination::gradient_not_finite);
  CHECK(bad.message == "lbfgs: gradient is NaN (index 2) at evaluation 3");

  // Errors of f itself pass through unchanged (not as a line-search failure).
  int evaluations = 0;
  const dpgen::LossGradient throwing = [&](const VectorXd& v, VectorXd& grad) {
    if (++evaluations == 2)
      throw std::domain_error("f failed");
    return rosenbrock(v, grad);
  };
  VectorXd t = rosenbrock_start(6);
  CHECK_THROWS_WITH_AS(dpgen::lbfgs_minimize(throwing, t, quiet), "f failed", std::domain_error);
}

TEST_CASE("optimizers take options structs") {
  dpgen::GradientDescentOptions gd_options;
  gd_options.learning_rate = 0.25;
  dpgen::GradientDescent gd(gd_options);
  VectorXd x = VectorXd::Ones(2), grad = VectorXd::Constant(2, 2.0);
  double loss = 0.0;
  const dpgen::LossGradient f = [](const VectorXd& v, VectorXd& g) {
    g = v;
    return 0.5 * v.squaredNorm();
  };
  gd.step(x, loss, grad, f);
  CHECK(x == VectorXd::Constant(2, 0.5)); // 1 - 0.25 * 2
  CHECK(loss == 0.25);
}

TEST_CASE("HIG with kappa = -1 is Gauss-Newton: one unit step solves linear least squares") {
  const LinearResidual p(8, VectorXd::LinSpaced(4, 3.0, 0.1), 21);
  const VectorXd x0 = dpgen_test::random_vector(4, 5);
  VectorXd x = x0;
  const dpgen::HigSummary s = dpgen::hig_minimize(p, x, hig_options(1.0, -1.0, 1e-12, 1));
  const VectorXd x_star = p.minimizer();
  CHECK(s.iterations == 1);
  CHECK(s.rank == 4);
  CHECK(s.termination == dpgen::Termination::max_iterations);
  // x1 = x0 - J^+ (A x0 - b) = A^+ b: cond(A) = 30, so ~30 eps relative error.
  CHECK((x - x_star).norm() <= 1e-13 * x_star.norm());
  CHECK(s.final_loss < s.initial_loss);
  VectorXd grad;
  CHECK(s.final_loss == doctest::Approx(p.loss(x_star, grad)).epsilon(1e-12));
  CHECK(grad.norm() <= 1e-12 * p.a.norm() * p.b.norm()); // the normal equations hold
}

TEST_CASE("HIG with kappa = +1 is a gradient-descent step with the same learning rate") {
  const LinearResidual p(6, (VectorXd(5) << 4.0, 2.0, 1.0, 0.5, 0.25).finished(), 31);
  const VectorXd x0 = dpgen_test::random_vector(5, 6);
  Eigen::MatrixXd jac;
  const VectorXd r = p(x0, jac);
  const dpgen::HigUpdate u = dpgen::hig_update(jac, r, hig_options(0.05, 1.0, 0.0, 1));

  const dpgen::LossGradient f = [&](const VectorXd& x, VectorXd& grad) { return p.loss(x, grad); };
  dpgen::GradientDescent gd({0.05});
  VectorXd x = x0, grad;
  double loss = f(x, grad);
  gd.step(x, loss, grad, f);
  // V Sigma U^T r = J^T r: the SVD's rounding, eps sigma_max |r| per entry.
  CHECK((x0 + u.step - x).norm() <= 1e-14 * (1.0 + x0.norm()));
  CHECK(u.rank == 5);
  CHECK((u.singular_values - (VectorXd(5) << 4.0, 2.0, 1.0, 0.5, 0.25).finished()).norm() <= 1e-14);
}

TEST_CASE("HIG truncation drops the direction of a tiny singular value") {
  const VectorXd sigma = (VectorXd(3) << 1.0, 1e-2, 1e-9).finished();
  const LinearResidual p(5, sigma, 41);
  const VectorXd x0 = VectorXd::Zero(3);
  Eigen::MatrixXd jac;
  const VectorXd r = p(x0, jac);
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(jac, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::MatrixXd v = svd.matrixV();
  const VectorXd c = svd.matrixU().transpose() * r;

  // truncation 1e-6: sigma_2 = 1e-9 < 1e-6 sigma_max is dropped, no step along v_2.
  const dpgen::HigUpdate kept = dpgen::hig_update(jac, r, hig_options(1.0, -0.5, 1e-6, 1));
  CHECK(kept.rank == 2);
  CHECK(std::abs(v.col(2).dot(kept.step)) <= 1e-14 * kept.step.norm());
  for (Eigen::Index i = 0; i < 2; ++i) // along v_i: -sigma_i^(-1/2) (u_i . r)
    CHECK(v.col(i).dot(kept.step) ==
          doctest::Approx(-c[i] / std::sqrt(svd.singularValues()[i])).epsilon(1e-10));

  // truncation 0: that direction takes a step sigma_2^(-1/2) ~ 3e4 times its component.
  const dpgen::HigUpdate all = dpgen::hig_update(jac, r, hig_options(1.0, -0.5, 0.0, 1));
  CHECK(all.rank == 3);
  CHECK(v.col(2).dot(all.step) ==
        doctest::Approx(-c[2] / std::sqrt(svd.singularValues()[2])).epsilon(1e-6));
  CHECK(std::abs(v.col(2).dot(all.step)) > 1e3 * std::abs(c[2]));
}

TEST_CASE("HIG on a wide Jacobian (fewer outputs than parameters, as a batch's) and r = dL/dy") {
  // y = A x with A 3x7; hig_update takes any gradient g = dL/dy in place of a residual.
  const Eigen::MatrixXd a =
      Eigen::Map<const Eigen::MatrixXd>(dpgen_test::random_vector(21, 61).data(), 3, 7);
  const VectorXd b = dpgen_test::random_vector(3, 62);
  // kappa = -1 from x = 0 with g = A x - b = -b: the minimum-norm step that fits y = b exactly.
  const dpgen::HigUpdate gn = dpgen::hig_update(a, -b, hig_options(1.0, -1.0, 0.0, 1));
  CHECK(gn.rank == 3);
  CHECK(gn.singular_values.size() == 3);
  CHECK((a * gn.step - b).norm() <= 1e-12 * b.norm());
  const VectorXd min_norm = a.completeOrthogonalDecomposition().pseudoInverse() * b;
  CHECK((gn.step - min_norm).norm() <= 1e-12 * min_norm.norm());
  // kappa = -1/2 with g = 2 (y - y*) / 4 (a mean squared error over 4 samples' worth), against
  // an independent SVD (Jacobi): dx = -eta V Sigma^(-1/2) U^T g.
  const VectorXd g = 0.5 * (a * dpgen_test::random_vector(7, 63) - b);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const VectorXd expected = -0.7 * svd.matrixV() *
                            svd.singularValues().array().rsqrt().matrix().asDiagonal() *
                            svd.matrixU().transpose() * g;
  const dpgen::HigUpdate half = dpgen::hig_update(a, g, hig_options(0.7, -0.5, 1e-10, 1));
  CHECK((half.step - expected).norm() <= 1e-12 * expected.norm());
  CHECK((half.singular_values - svd.singularValues()).norm() <= 1e-12 * svd.singularValues()[0]);
  // The decomposition is a template parameter: Jacobi's SVD gives the same update as the
  // default BDCSVD (which hands a matrix with fewer than 16 rows or columns to Jacobi itself,
  // hence 20 x 30).
  const Eigen::MatrixXd wide =
      Eigen::Map<const Eigen::MatrixXd>(dpgen_test::random_vector(600, 64).data(), 20, 30);
  const VectorXd gw = dpgen_test::random_vector(20, 65);
  const dpgen::HigUpdate bdc = dpgen::hig_update(wide, gw, hig_options(0.7, -0.5, 1e-10, 1));
  const dpgen::HigUpdate jacobi = dpgen::hig_update<Eigen::JacobiSVD<Eigen::MatrixXd>>(
      wide, gw, hig_options(0.7, -0.5, 1e-10, 1));
  CHECK(jacobi.rank == 20);
  CHECK((jacobi.step - bdc.step).norm() <= 1e-12 * bdc.step.norm());
}

TEST_CASE("HIG beats GD on an ill-conditioned least-squares problem in the same iterations") {
  // Singular values 1 .. 1e-3 (cond(J) = 1e3, cond(J^T J) = 1e6).
  VectorXd sigma(10);
  for (Eigen::Index i = 0; i < sigma.size(); ++i)
    sigma[i] = std::pow(10.0, -3.0 * double(i) / 9.0);
  const LinearResidual p(12, sigma, 51);
  const VectorXd x0 = VectorXd::Zero(10);
  const int iterations = 50;
  VectorXd grad;
  const double optimum = p.loss(p.minimizer(), grad);

  // GD at its best fixed rate 1 / sigma_max^2: direction i contracts by 1 - sigma_i^2 per step.
  dpgen::GradientDescent gd({1.0 / (sigma[0] * sigma[0])});
  const dpgen::LossGradient f = [&](const VectorXd& x, VectorXd& g) { return p.loss(x, g); };
  const double gd_loss = p.loss(run(gd, f, x0, iterations), grad);

  // HIG (kappa = -1/2) at rate 1 / sigma_max^(1/2): direction i contracts by 1 - sigma_i^(1/2).
  VectorXd x = x0;
  const dpgen::HigSummary s =
      dpgen::hig_minimize(p, x, hig_options(1.0 / std::sqrt(sigma[0]), -0.5, 1e-6, iterations));
  CHECK(s.iterations == iterations);
  CHECK(s.termination == dpgen::Termination::max_iterations);
  CHECK(s.final_loss == doctest::Approx(p.loss(x, grad)).epsilon(1e-14));
  // Excess losses over the optimum: HIG's slowest factor (1 - 0.0316)^(2*50) ~ 0.04 against
  // GD's (1 - 1e-6)^(2*50) ~ 1 on the smallest direction.
  CAPTURE(gd_loss - optimum);
  CAPTURE(s.final_loss - optimum);
  CHECK(s.final_loss - optimum < 0.1 * (gd_loss - optimum));
}

TEST_CASE("HIG on a nonlinear residual, with the Jacobian assembled from tangents") {
  // Rosenbrock as residuals: r = (1 - x0, 10 (x1 - x0^2)), minimum 0 at (1, 1).
  const auto residual = [](const VectorXd& x) {
    return VectorXd((VectorXd(2) << 1.0 - x[0], 10.0 * (x[1] - x[0] * x[0])).finished());
  };
  const dpgen::JacobianVectorProduct jvp = [](const VectorXd& x, const VectorXd& v) {
    return VectorXd((VectorXd(2) << -v[0], 10.0 * (v[1] - 2.0 * x[0] * v[0])).finished());
  };
  const dpgen::ResidualJacobian f = [&](const VectorXd& x, Eigen::MatrixXd& jac) {
    jac = dpgen::jacobian(jvp, nullptr, x, 2);
    return residual(x);
  };
  dpgen::HigOptions o = hig_options(1.0, -1.0, 1e-12, 50);
  o.loss_tolerance = 1e-24;
  VectorXd x = (VectorXd(2) << -1.2, 1.0).finished();
  const dpgen::HigSummary gn = dpgen::hig_minimize(f, x, o);
  CHECK(gn.termination == dpgen::Termination::loss_tolerance);
  CHECK(gn.iterations <= 5); // Gauss-Newton on a zero-residual problem: quadratic convergence
  CHECK((x - VectorXd::Ones(2)).norm() < 1e-10);
  CHECK(gn.message.rfind("hig: converged after ", 0) == 0);

  // The half-inverse update converges too: near (1, 1) direction i contracts by
  // 1 - eta sigma_i^(1/2), sigma = (22.4, 0.45), so eta = 0.2 < 2 / sqrt(22.4) is stable.
  o.exponent = -0.5;
  o.learning_rate = 0.2;
  o.max_iterations = 200;
  x = (VectorXd(2) << -1.2, 1.0).finished();
  const dpgen::HigSummary half = dpgen::hig_minimize(f, x, o);
  CHECK(half.final_loss < 1e-6 * half.initial_loss);
}

TEST_CASE("HIG stops: zero update, loss met at the start, NaN and Inf, bad options") {
  // A zero Jacobian: no direction survives, the update is zero.
  const dpgen::ResidualJacobian flat = [](const VectorXd& x, Eigen::MatrixXd& jac) {
    jac.setZero(2, x.size());
    return VectorXd(VectorXd::Ones(2));
  };
  VectorXd x = VectorXd::Ones(3);
  const dpgen::HigSummary s = dpgen::hig_minimize(flat, x);
  CHECK(s.termination == dpgen::Termination::step_tolerance);
  CHECK(s.iterations == 1);
  CHECK(s.rank == 0);
  CHECK(x == VectorXd::Ones(3));
  CHECK(s.message == "hig: stopped after 1 iterations, update norm <= tolerance 0, loss 1");
  CHECK(std::string(dpgen::to_string(s.termination)) == "step_tolerance");

  // Already at the tolerance: no update, no second evaluation.
  const LinearResidual p(4, VectorXd::Ones(2), 61);
  VectorXd at = p.minimizer();
  dpgen::HigOptions loose;
  loose.loss_tolerance = 10.0;
  const dpgen::HigSummary none = dpgen::hig_minimize(p, at, loose);
  CHECK(none.iterations == 0);
  CHECK(none.termination == dpgen::Termination::loss_tolerance);

  // The residual turns NaN at the second iterate; the Jacobian Inf at the first.
  int calls = 0;
  const dpgen::ResidualJacobian nan_later = [&](const VectorXd& y, Eigen::MatrixXd& jac) {
    jac = Eigen::MatrixXd::Identity(2, 2);
    VectorXd r = y;
    if (++calls == 3)
      r[1] = std::numeric_limits<double>::quiet_NaN();
    return r;
  };
  VectorXd y = VectorXd::Ones(2);
  CHECK_THROWS_WITH_AS(dpgen::hig_minimize(nan_later, y, hig_options(0.5, -0.5, 1e-6, 10)),
                       "hig: residual is NaN at index 1 in iteration 2", dpgen::OptimizationError);
  // The same stop reported in the summary instead (throw_on_failure off).
  calls = 0;
  y = VectorXd::Ones(2);
  dpgen::HigOptions quiet = hig_options(0.5, -0.5, 1e-6, 10);
  quiet.throw_on_failure = false;
  const dpgen::HigSummary nan = dpgen::hig_minimize(nan_later, y, quiet);
  CHECK(nan.termination == dpgen::Termination::loss_not_finite);
  CHECK(nan.failed());
  CHECK(nan.iterations == 2);
  CHECK(nan.message == "hig: residual is NaN at index 1 in iteration 2");
  // and in the exception's summary
  calls = 0;
  y = VectorXd::Ones(2);
  try {
    dpgen::hig_minimize(nan_later, y, hig_options(0.5, -0.5, 1e-6, 10));
    FAIL("expected an OptimizationError");
  } catch (const dpgen::OptimizationError& e) {
    REQUIRE(e.has_summary());
    CHECK(e.summary().termination == dpgen::Termination::loss_not_finite);
    CHECK(e.summary().iterations == 2);
  }
  // max_iterations and the time limit
  y = VectorXd::Ones(2);
  const dpgen::ResidualJacobian identity = [](const VectorXd& v, Eigen::MatrixXd& jac) {
    jac = Eigen::MatrixXd::Identity(2, 2);
    return v;
  };
  const dpgen::HigSummary limit = dpgen::hig_minimize(identity, y, hig_options(0.5, -0.5, 1e-6, 3));
  CHECK(limit.termination == dpgen::Termination::max_iterations);
  CHECK(limit.iterations == 3);
  dpgen::HigOptions timed = hig_options(0.01, -0.5, 1e-6, 1000000000);
  timed.time_limit = 0.0;
  y = VectorXd::Ones(2);
  const dpgen::HigSummary out_of_time = dpgen::hig_minimize(identity, y, timed);
  CHECK(out_of_time.termination == dpgen::Termination::time_limit);
  CHECK(out_of_time.iterations == 1);
  const dpgen::ResidualJacobian inf_jac = [](const VectorXd& z, Eigen::MatrixXd& jac) {
    jac = Eigen::MatrixXd::Identity(2, 2);
    jac(1, 0) = std::numeric_limits<double>::infinity();
    return z;
  };
  VectorXd z = VectorXd::Ones(2);
  CHECK_THROWS_WITH_AS(dpgen::hig_minimize(inf_jac, z),
                       "hig: Jacobian is Inf at (1, 0) in iteration 0", dpgen::OptimizationError);
  z = VectorXd::Ones(2);
  dpgen::HigOptions quiet_inf;
  quiet_inf.throw_on_failure = false;
  CHECK(dpgen::hig_minimize(inf_jac, z, quiet_inf).termination ==
        dpgen::Termination::gradient_not_finite);
  CHECK_THROWS_WITH_AS(
      dpgen::hig_update(Eigen::MatrixXd::Identity(2, 2), VectorXd::Constant(2, std::nan(""))),
      "hig: residual is NaN at index 0", dpgen::OptimizationError);

  // Sizes and options.
  const dpgen::ResidualJacobian wrong = [](const VectorXd&, Eigen::MatrixXd& jac) {
    jac.setZero(2, 2);
    return VectorXd(VectorXd::Ones(2));
  };
  VectorXd w = VectorXd::Ones(3);
  CHECK_THROWS_WITH_AS(dpgen::hig_minimize(wrong, w), "hig: Jacobian is 2x2, expected 2x3",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::hig_update(Eigen::MatrixXd::Identity(2, 2), VectorXd::Ones(3)),
                       "hig: residual has size 3, expected 2", std::invalid_argument);
  CHECK_THROWS_AS(dpgen::hig_update(Eigen::MatrixXd::Identity(2, 2), VectorXd::Ones(2),
                                    hig_options(0.0, -0.5, 1e-6, 1)),
                  std::invalid_argument);
  CHECK_THROWS_AS(dpgen::hig_update(Eigen::MatrixXd::Identity(2, 2), VectorXd::Ones(2),
                                    hig_options(1.0, -0.5, 1.0, 1)),
                  std::invalid_argument);
}
