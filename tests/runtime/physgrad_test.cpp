// Tests of dpgen/physgrad.hpp: the PG update on the book's y = (x0, x1^2) example against its
// closed form (and the notebook's printed iterates); one PG step with an exact inverse solves
// a linear problem; the regularized inverse against a dense solve and its limits; errors.
#include "dpgen/physgrad.hpp"

#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using dpgen_test::random_vector;

// The book's "simple example": y(x) = (x0, x1^2), L = |y|^2, inverse y^-1 = (y0, sqrt(y1)).
dpgen::PhysicalGradientProblem book_example() {
  dpgen::PhysicalGradientProblem p;
  p.forward = [](const VectorXd& x) { return VectorXd((VectorXd(2) << x[0], x[1] * x[1]).finished()); };
  p.inverse = [](const VectorXd& y, const VectorXd&) {
    return VectorXd((VectorXd(2) << y[0], std::sqrt(y[1])).finished());
  };
  p.loss = dpgen::l2_loss_newton(VectorXd::Zero(2));
  return p;
}

TEST_CASE("PG on the book's example: y shrinks by 1 - lr per step, x = (3 q^k, 3 q^(k/2))") {
  const auto p = book_example();
  dpgen::PgOptions o;
  o.learning_rate = 0.3;
  VectorXd x(2);
  x << 3.0, 3.0;
  for (int k = 1; k <= 10; ++k) {
    x = dpgen::physical_update(p, x, o);
    CHECK(x[0] == doctest::Approx(3.0 * std::pow(0.7, k)).epsilon(1e-14));
    CHECK(x[1] == doctest::Approx(3.0 * std::pow(0.7, 0.5 * k)).epsilon(1e-14));
  }
  // The notebook (float32, JAX) prints "PG iter 9: [0.08474258 0.50421]".
  CHECK(x[0] == doctest::Approx(0.08474258).epsilon(1e-6));
  CHECK(x[1] == doctest::Approx(0.50421).epsilon(1e-5));
}

TEST_CASE("with an exact inverse and lr 1, one PG step solves a linear problem; pg_minimize") {
  const MatrixXd a = MatrixXd::Identity(5, 5) + 0.3 * Eigen::Map<const MatrixXd>(
                                                           random_vector(25, 1).data(), 5, 5);
  const VectorXd target = random_vector(5, 2);
  dpgen::PhysicalGradientProblem p;
  p.forward = [&](const VectorXd& x) -> VectorXd { return a * x; };
  p.inverse = [&](const VectorXd& y, const VectorXd&) -> VectorXd {
    return a.partialPivLu().solve(y);
  };
  p.loss = dpgen::l2_loss_newton(target);
  VectorXd x = random_vector(5, 3);
  dpgen::PgOptions o;
  o.max_iterations = 5;
  o.loss_tolerance = 1e-24;
  const dpgen::PgSummary s = dpgen::pg_minimize(p, x, o);
  CHECK(s.termination == dpgen::Termination::loss_tolerance);
  CHECK(s.iterations == 1);
  CHECK((a * x - target).norm() < 1e-12);
  CHECK(s.initial_loss > 0.1);
  // lr 1/2 halves the residual in y each step: loss / 4 per step.
  x = random_vector(5, 3);
  o.learning_rate = 0.5;
  o.loss_tolerance = -1.0;
  const dpgen::PgSummary half = dpgen::pg_minimize(p, x, o);
  CHECK(half.termination == dpgen::Termination::max_iterations);
  CHECK(half.iterations == 5);
  CHECK(half.final_loss == doctest::Approx(half.initial_loss / std::pow(4.0, 5)).epsilon(1e-10));
  CHECK(half.message.rfind("pg: max_iterations after 5 updates", 0) == 0);
}

TEST_CASE("pg_minimize: NaN loss and non-finite inverse are termination reasons") {
  const VectorXd target = VectorXd::Ones(3);
  dpgen::PhysicalGradientProblem p;
  int calls = 0;
  p.forward = [&](const VectorXd& x) -> VectorXd { return x; };
  p.inverse = [](const VectorXd& y, const VectorXd&) -> VectorXd { return y; };
  const auto l2 = dpgen::l2_loss_newton(target);
  p.loss = [&](const VectorXd& y, VectorXd& newton) {
    const double loss = l2(y, newton);
    return ++calls == 3 ? std::numeric_limits<double>::quiet_NaN() : loss;
  };
  dpgen::PgOptions o;
  o.learning_rate = 0.5;
  o.max_iterations = 10;
  VectorXd x = VectorXd::Zero(3);
  try {
    dpgen::pg_minimize(p, x, o);
    FAIL("expected an OptimizationError");
  } catch (const dpgen::OptimizationError& e) {
    REQUIRE(e.has_summary());
    CHECK(e.summary().termination == dpgen::Termination::loss_not_finite);
    CHECK(e.summary().iterations == 2);
    CHECK(std::string(e.what()) == "pg: loss is nan at the current x (after 2 updates)");
  }
  calls = 0;
  x = VectorXd::Zero(3);
  o.throw_on_failure = false;
  const dpgen::PgSummary nan = dpgen::pg_minimize(p, x, o);
  CHECK(nan.termination == dpgen::Termination::loss_not_finite);
  CHECK(nan.failed());
  CHECK(nan.iterations == 2);
  CHECK(x == VectorXd::Constant(3, 0.75)); // the last finite iterate: 0 -> 0.5 -> 0.75

  p.loss = l2;
  p.inverse = [](const VectorXd& y, const VectorXd&) -> VectorXd {
    return VectorXd::Constant(y.size(), std::numeric_limits<double>::infinity());
  };
  x = VectorXd::Zero(3);
  const dpgen::PgSummary inf = dpgen::pg_minimize(p, x, o);
  CHECK(inf.termination == dpgen::Termination::gradient_not_finite);
  CHECK(inf.message == "pg: inverse simulator's result contains inf at index 0 (after 0 updates)");

  // The time limit (0: stops after the first evaluation, before any update).
  p.inverse = [](const VectorXd& y, const VectorXd&) -> VectorXd { return y; };
  o.time_limit = 0.0;
  x = VectorXd::Zero(3);
  const dpgen::PgSummary timed = dpgen::pg_minimize(p, x, o);
  CHECK(timed.termination == dpgen::Termination::time_limit);
  CHECK(timed.iterations == 0);
}

TEST_CASE("pg_minimize: a converged run or one at its limit stops before the inverse solve") {
  // The inverse fails wherever it is called: a run that has converged, or has no update left,
  // must stop with that reason and never call it.
  const VectorXd target = VectorXd::Ones(2);
  dpgen::PhysicalGradientProblem p;
  int inverse_calls = 0;
  p.forward = [](const VectorXd& x) -> VectorXd { return x; };
  p.inverse = [&](const VectorXd& y, const VectorXd&) -> VectorXd {
    ++inverse_calls;
    return VectorXd::Constant(y.size(), std::numeric_limits<double>::infinity());
  };
  p.loss = dpgen::l2_loss_newton(target);
  dpgen::PgOptions o;
  o.loss_tolerance = 1e-12;
  VectorXd x = target; // loss 0: converged at the start
  const dpgen::PgSummary done = dpgen::pg_minimize(p, x, o);
  CHECK(done.termination == dpgen::Termination::loss_tolerance);
  CHECK(done.iterations == 0);
  CHECK(inverse_calls == 0);

  o.loss_tolerance = 0.0;
  o.max_iterations = 0; // no update allowed
  x = VectorXd::Zero(2);
  const dpgen::PgSummary limit = dpgen::pg_minimize(p, x, o);
  CHECK(limit.termination == dpgen::Termination::max_iterations);
  CHECK(limit.final_loss == doctest::Approx(2.0));
  CHECK(inverse_calls == 0);
}

TEST_CASE("regularized inverse: the dense Tikhonov solution; lambda -> 0 inverts exactly") {
  // A smoothing operator (three Jacobi-style diffusion passes), applied as a dense matrix.
  const int n = 16;
  MatrixXd d = MatrixXd::Identity(n, n) * 0.5;
  for (int i = 0; i < n; ++i) {
    d(i, (i + 1) % n) += 0.25;
    d(i, (i + n - 1) % n) += 0.25;
  }
  const MatrixXd p = d * d * d;
  const auto apply = [&](const VectorXd& v, VectorXd& out) { out = p * v; };
  const auto apply_t = [&](const VectorXd& v, VectorXd& out) { out = p.transpose() * v; };
  const VectorXd x = random_vector(n, 4), y = random_vector(n, 5);
  const double lambda = 1e-3;
  const VectorXd got = dpgen::regularized_inverse(apply, apply_t, y, x, lambda);
  const MatrixXd normal = p.transpose() * p + lambda * MatrixXd::Identity(n, n);
  const VectorXd expected = x + normal.ldlt().solve(p.transpose() * (y - p * x));
  CHECK((got - expected).norm() < 1e-8 * expected.norm());
  // P is singular (the checkerboard mode is wiped out): large lambda keeps x, the
  // regularized solve stays finite where the exact inverse does not exist.
  const VectorXd kept = dpgen::regularized_inverse(apply, apply_t, y, x, 1e8);
  CHECK((kept - x).norm() < 1e-6 * x.norm());
  // For an invertible P, small lambda recovers P^-1 y.
  const MatrixXd q = MatrixXd::Identity(n, n) + 0.5 * d;
  const auto apply_q = [&](const VectorXd& v, VectorXd& out) { out = q * v; };
  const auto apply_qt = [&](const VectorXd& v, VectorXd& out) { out = q.transpose() * v; };
  const VectorXd inv = dpgen::regularized_inverse(apply_q, apply_qt, y, x, 1e-12);
  CHECK((q * inv - y).norm() < 1e-8 * y.norm());
}

TEST_CASE("bad input is a clear error") {
  auto p = book_example();
  VectorXd x(2);
  x << 3.0, 3.0;
  dpgen::PgOptions o;
  o.learning_rate = -1.0;
  CHECK_THROWS_WITH_AS(dpgen::physical_update(p, x, o),
                       "pg: learning_rate must be positive and finite (got -1)",
                       std::invalid_argument);
  o = {};
  p.inverse = [](const VectorXd&, const VectorXd&) { return VectorXd::Zero(3).eval(); };
  CHECK_THROWS_WITH_AS(dpgen::physical_update(p, x, o),
                       "pg: inverse simulator's result has size 3, expected 2",
                       std::invalid_argument);
  p.inverse = nullptr;
  CHECK_THROWS_WITH_AS(dpgen::physical_update(p, x, o),
                       "pg: the problem needs forward, inverse and loss callables",
                       std::invalid_argument);
  p = book_example();
  x[0] = std::nan("");
  CHECK_THROWS_WITH_AS(dpgen::physical_update(p, x, o), "pg: x contains nan at index 0",
                       std::invalid_argument);
  const auto identity = [](const VectorXd& v, VectorXd& out) { out = v; };
  CHECK_THROWS_WITH_AS(dpgen::regularized_inverse(identity, identity, VectorXd::Ones(2),
                                                  VectorXd::Ones(2), 0.0),
                       "regularized inverse: lambda must be positive (got 0)",
                       std::invalid_argument);
}

} // namespace
