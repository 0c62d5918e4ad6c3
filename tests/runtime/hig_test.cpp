// Tests of dpgen/hig.hpp: the HIG update against its formula with an independent SVD (Jacobi);
// exponent -1 is the Gauss-Newton / least-squares step and +1 the gradient step; truncation
// drops exactly the small singular directions; hig_minimize's stopping rules; bad input.
#include "dpgen/optim.hpp" // includes hig.hpp, as users get it

#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using dpgen_test::random_vector;

MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  return Eigen::Map<const MatrixXd>(random_vector(rows * cols, seed).data(), rows, cols);
}

// L(x) = 1/2 |A x - b|^2: y = A x, dL/dy = A x - b, dy/dx = A.
struct LinearLeastSquares {
  MatrixXd a;
  VectorXd b;
  double operator()(const VectorXd& x, VectorXd& g, MatrixXd& j) const {
    g = a * x - b;
    j = a;
    return 0.5 * g.squaredNorm();
  }
};

TEST_CASE("exponent -1 is the Gauss-Newton step: one update solves linear least squares") {
  const LinearLeastSquares p{random_matrix(9, 4, 1), random_vector(9, 2)};
  VectorXd x = random_vector(4, 3), g;
  MatrixXd j;
  p(x, g, j);
  dpgen::HigOptions o;
  o.exponent = -1.0;
  const VectorXd x_new = x + dpgen::hig_update(j, g, o);
  const VectorXd x_ls = p.a.colPivHouseholderQr().solve(p.b); // the least-squares solution
  CHECK((x_new - x_ls).norm() < 1e-12 * x_ls.norm());
  // Gauss-Newton written out: dx = -(A^T A)^-1 A^T (A x - b).
  const VectorXd dx_gn = -(p.a.transpose() * p.a).ldlt().solve(p.a.transpose() * g);
  CHECK((x_new - x - dx_gn).norm() < 1e-12 * dx_gn.norm());
}

TEST_CASE("underdetermined with exponent -1: the minimum-norm step that fits exactly") {
  const LinearLeastSquares p{random_matrix(3, 7, 4), random_vector(3, 5)};
  VectorXd x = VectorXd::Zero(7), g;
  MatrixXd j;
  p(x, g, j);
  dpgen::HigOptions o;
  o.exponent = -1.0;
  const VectorXd dx = dpgen::hig_update(j, g, o);
  CHECK((p.a * dx - p.b).norm() < 1e-12);
  const VectorXd dx_min = p.a.completeOrthogonalDecomposition().pseudoInverse() * p.b;
  CHECK((dx - dx_min).norm() < 1e-12 * dx_min.norm());
}

TEST_CASE("exponent -1/2 matches V S^-1/2 U^T g from a Jacobi SVD; exponent 1 is -lr J^T g") {
  const MatrixXd j = random_matrix(6, 10, 6);
  const VectorXd g = random_vector(6, 7);
  dpgen::HigOptions o;
  o.learning_rate = 0.7;
  const Eigen::JacobiSVD<MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const VectorXd s_half = svd.singularValues().array().rsqrt().matrix();
  const VectorXd expected =
      -0.7 * svd.matrixV() * s_half.asDiagonal() * svd.matrixU().transpose() * g;
  dpgen::HigStep step;
  const VectorXd dx = dpgen::hig_update(j, g, o, &step);
  CHECK((dx - expected).norm() < 1e-12 * expected.norm());
  CHECK(step.kept == 6);
  CHECK(step.singular_values == 6);
  CHECK(step.largest_singular_value == doctest::Approx(svd.singularValues()[0]).epsilon(1e-12));
  o.exponent = 1.0;
  CHECK((dpgen::hig_update(j, g, o) + 0.7 * j.transpose() * g).norm() < 1e-12 * g.norm());
}

TEST_CASE("truncation drops singular values at or below truncation * S_max, and only those") {
  // J = U diag(1, 1e-3, 1e-12) V^T with orthonormal U (5x3) and orthogonal V (3x3).
  const Eigen::HouseholderQR<MatrixXd> qu(random_matrix(5, 3, 8)), qv(random_matrix(3, 3, 9));
  const MatrixXd u = qu.householderQ() * MatrixXd::Identity(5, 3);
  const MatrixXd v = qv.householderQ() * MatrixXd::Identity(3, 3);
  const MatrixXd j = u * VectorXd((VectorXd(3) << 1.0, 1e-3, 1e-12).finished()).asDiagonal() *
                     v.transpose();
  const VectorXd g = random_vector(5, 10);
  dpgen::HigOptions o;
  dpgen::HigStep step;
  o.truncation = 1e-10;
  const VectorXd kept_two = dpgen::hig_update(j, g, o, &step);
  CHECK(step.kept == 2);
  CHECK(step.smallest_kept_singular_value == doctest::Approx(1e-3).epsilon(1e-6));
  CHECK(std::abs(v.col(2).dot(kept_two)) < 1e-9 * kept_two.norm()); // nothing along v3
  o.truncation = 1e-2;
  dpgen::hig_update(j, g, o, &step);
  CHECK(step.kept == 1);
  o.truncation = 0.0; // keep all: the 1e-12 direction is amplified by 1e6
  const VectorXd all = dpgen::hig_update(j, g, o, &step);
  CHECK(step.kept == 3);
  CHECK(std::abs(v.col(2).dot(all)) > 1e3 * kept_two.norm());
}

TEST_CASE("hig_minimize: Gauss-Newton on a nonlinear fit, stopping rules, a zero Jacobian") {
  // Fit y_i = exp(x0 t_i) + x1 to data made with (0.5, -1): a zero-residual problem where
  // Gauss-Newton converges quadratically.
  const VectorXd t = VectorXd::LinSpaced(8, 0.0, 1.0);
  const VectorXd data = (0.5 * t).array().exp() - 1.0;
  const dpgen::LossOutputsJacobian f = [&](const VectorXd& x, VectorXd& g, MatrixXd& j) {
    const VectorXd e = (x[0] * t).array().exp();
    g = e.array() + x[1] - data.array();
    j.resize(8, 2);
    j.col(0) = t.cwiseProduct(e);
    j.col(1).setOnes();
    return 0.5 * g.squaredNorm();
  };
  VectorXd x(2);
  x << 0.0, 0.0;
  dpgen::HigOptions o;
  o.exponent = -1.0;
  o.loss_tolerance = 1e-24;
  o.max_iterations = 20;
  dpgen::HigSummary s = dpgen::hig_minimize(f, x, o);
  CHECK(s.termination == dpgen::HigTermination::loss_tolerance);
  CHECK(s.iterations <= 8);
  CHECK(x[0] == doctest::Approx(0.5).epsilon(1e-10));
  CHECK(x[1] == doctest::Approx(-1.0).epsilon(1e-10));
  CHECK(s.message.find("hig: loss_tolerance after") == 0);

  // The half-inverse (-1/2) converges on it too, more slowly; stops at the iteration limit.
  x << 0.0, 0.0;
  o.exponent = -0.5;
  o.loss_tolerance = -std::numeric_limits<double>::infinity();
  o.learning_rate = 0.5;
  o.max_iterations = 30;
  s = dpgen::hig_minimize(f, x, o);
  CHECK(s.termination == dpgen::HigTermination::max_iterations);
  CHECK(s.iterations == 30);
  CHECK(s.final_loss < 1e-6 * s.initial_loss);

  // A step smaller than step_tolerance stops it.
  o.step_tolerance = 1e100;
  s = dpgen::hig_minimize(f, x, o);
  CHECK(s.termination == dpgen::HigTermination::step_tolerance);
  CHECK(s.iterations == 1);

  const dpgen::LossOutputsJacobian flat = [](const VectorXd&, VectorXd& g, MatrixXd& j) {
    g = VectorXd::Ones(3);
    j = MatrixXd::Zero(3, 2);
    return 1.5;
  };
  s = dpgen::hig_minimize(flat, x, o);
  CHECK(s.termination == dpgen::HigTermination::no_direction);
  CHECK(s.iterations == 0);
  CHECK(s.last_step.kept == 0);
}

TEST_CASE("bad input is a clear error") {
  const MatrixXd j = MatrixXd::Ones(3, 2);
  dpgen::HigOptions o;
  CHECK_THROWS_WITH_AS(dpgen::hig_update(j, VectorXd::Ones(2), o),
                       "hig: loss gradient dL/dy has size 2, expected 3", std::invalid_argument);
  MatrixXd j_nan = j;
  j_nan(1, 1) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH_AS(dpgen::hig_update(j_nan, VectorXd::Ones(3), o),
                       "hig: Jacobian column 1 contains inf at index 1", std::invalid_argument);
  o.truncation = 1.0;
  CHECK_THROWS_WITH_AS(dpgen::hig_update(j, VectorXd::Ones(3), o),
                       "hig: truncation must be in [0, 1) (got 1)", std::invalid_argument);
  o = {};
  o.learning_rate = 0.0;
  CHECK_THROWS_WITH_AS(dpgen::HalfInverseGradient{o},
                       "hig: learning_rate must be positive and finite (got 0)",
                       std::invalid_argument);
  o = {};
  o.exponent = std::nan("");
  CHECK_THROWS_WITH_AS(dpgen::HalfInverseGradient{o}, "hig: exponent must be finite (got nan)",
                       std::invalid_argument);
  dpgen::HalfInverseGradient hig;
  VectorXd x = VectorXd::Zero(4);
  const dpgen::LossOutputsJacobian wrong = [](const VectorXd&, VectorXd& g, MatrixXd& jac) {
    g = VectorXd::Ones(3);
    jac = MatrixXd::Ones(3, 2);
    return 1.0;
  };
  CHECK_THROWS_WITH_AS(hig.step(x, wrong), "hig: Jacobian's column count has size 2, expected 4",
                       std::invalid_argument);
}

} // namespace
