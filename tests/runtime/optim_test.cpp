// Tests of dpgen/optim.hpp: gradient descent and Adam against their update formulas and on a
// quadratic; L-BFGS (stepwise and LBFGSSolver-driven) on a quadratic and on Rosenbrock.
#include "dpgen/optim.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstring>
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

} // namespace

TEST_CASE("gradient descent: the update rule and convergence on a quadratic") {
  const Quadratic q;
  const VectorXd x0 = VectorXd::Ones(q.n);
  dpgen::GradientDescent gd(0.05);
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
  dpgen::GradientDescent tuned(1.0 / q.largest_eigenvalue());
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
  LBFGSpp::LBFGSParam<double> param;
  param.epsilon = 1e-10;
  param.epsilon_rel = 0.0;
  param.max_iterations = 500;
  VectorXd x = rosenbrock_start(10);
  const dpgen::LbfgsSummary summary = dpgen::lbfgs_minimize(rosenbrock, x, param);
  CHECK(summary.iterations > 10);
  CHECK((x - VectorXd::Ones(10)).norm() < 1e-8);
  CHECK(summary.grad_norm <= 1e-10);
  CHECK(summary.loss < 1e-16);

  dpgen::Lbfgs stepwise(param);
  const VectorXd y = run(stepwise, rosenbrock, rosenbrock_start(10), summary.iterations);
  CHECK(std::memcmp(x.data(), y.data(), sizeof(double) * 10) == 0);
}

TEST_CASE("optimizer errors") {
  CHECK_THROWS_WITH_AS(dpgen::GradientDescent(0.0), "gd: learning rate must be positive (got 0)",
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
}
