// Tests of dpgen/jacobian.hpp: tangent (by columns) and adjoint (by rows) assembly agree with
// each other, with the analytic Jacobian and with central differences, on a small nonlinear
// function and on the generated upwind_step_tangent / upwind_step_adjoint; size errors throw.
#include "dpgen/jacobian.hpp"

#include "kernels.hpp"
#include "test_support.hpp"
#include "upwind_step_adjoint.hpp"
#include "upwind_step_tangent.hpp"

#include <doctest/doctest.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// f: R^3 -> R^4, f(x) = (x0 x1 + sin x2, exp(x0) - x1^2 x2, x2^3, x0 + 2 x1).
VectorXd f_small(const VectorXd& x) {
  VectorXd y(4);
  y << x[0] * x[1] + std::sin(x[2]), std::exp(x[0]) - x[1] * x[1] * x[2], std::pow(x[2], 3),
      x[0] + 2.0 * x[1];
  return y;
}

MatrixXd jacobian_small(const VectorXd& x) {
  MatrixXd j(4, 3);
  j << x[1], x[0], std::cos(x[2]),                      //
      std::exp(x[0]), -2.0 * x[1] * x[2], -x[1] * x[1], //
      0.0, 0.0, 3.0 * x[2] * x[2],                      //
      1.0, 2.0, 0.0;
  return j;
}

// The products written out by hand, not through jacobian_small, so the modes are checked
// against an independent transcription.
VectorXd jvp_small(const VectorXd& x, const VectorXd& v) {
  VectorXd y(4);
  y << x[1] * v[0] + x[0] * v[1] + std::cos(x[2]) * v[2],
      std::exp(x[0]) * v[0] - 2.0 * x[1] * x[2] * v[1] - x[1] * x[1] * v[2],
      3.0 * x[2] * x[2] * v[2], v[0] + 2.0 * v[1];
  return y;
}

VectorXd vjp_small(const VectorXd& x, const VectorXd& w) {
  VectorXd g(3);
  g << x[1] * w[0] + std::exp(x[0]) * w[1] + w[3],
      x[0] * w[0] - 2.0 * x[1] * x[2] * w[1] + 2.0 * w[3],
      std::cos(x[2]) * w[0] - x[1] * x[1] * w[1] + 3.0 * x[2] * x[2] * w[2];
  return g;
}

double max_abs(const MatrixXd& a) { return a.cwiseAbs().maxCoeff(); }

// upwind_step as R^{2n} -> R^n: x = (d, u), y = d_next.
struct Upwind {
  int n = 12;
  double dt = 0.3, dx = 0.7;
  VectorXd forward(const VectorXd& x) const {
    VectorXd y(n);
    upwind_step(x.data(), x.data() + n, y.data(), n, dt, dx);
    return y;
  }
  VectorXd jvp(const VectorXd& x, const VectorXd& v) const {
    VectorXd y(n), y_dot(n);
    upwind_step_tangent(x.data(), v.data(), x.data() + n, v.data() + n, y.data(), y_dot.data(), n,
                        dt, dx);
    return y_dot;
  }
  VectorXd vjp(const VectorXd& x, const VectorXd& w) const {
    VectorXd g = VectorXd::Zero(2 * n); // the adjoint accumulates: start from zero
    upwind_step_adjoint(x.data(), g.data(), x.data() + n, g.data() + n, w.data(), n, dt, dx);
    return g;
  }
};

} // namespace

TEST_CASE("jacobian: tangent and adjoint assembly of a nonlinear function") {
  const VectorXd x = (VectorXd(3) << 0.3, -1.2, 0.7).finished();
  const MatrixXd by_columns = dpgen::jacobian_by_columns(jvp_small, x, 4);
  const MatrixXd by_rows = dpgen::jacobian_by_rows(vjp_small, x, 4);
  REQUIRE(by_columns.rows() == 4);
  REQUIRE(by_columns.cols() == 3);
  REQUIRE(by_rows.rows() == 4);
  REQUIRE(by_rows.cols() == 3);
  const MatrixXd exact = jacobian_small(x);
  // Both modes evaluate the same expressions in a different order: agreement to rounding.
  CHECK(max_abs(by_columns - by_rows) <= 1e-12);
  CHECK(max_abs(by_columns - exact) <= 1e-12);
  // Central differences: truncation h^2 |f'''| / 6 ~ 1e-10 plus rounding eps |f| / h ~ 1e-11.
  CHECK(max_abs(by_columns - dpgen::jacobian_central_difference(f_small, x)) <= 1e-8 * (1.0 + max_abs(exact)));

  // n = 3 inputs <= m = 4 outputs: three tangents beat four adjoints.
  dpgen::JacobianMode mode = dpgen::JacobianMode::adjoint;
  CHECK(dpgen::jacobian(jvp_small, vjp_small, x, 4, &mode) == by_columns);
  CHECK(mode == dpgen::JacobianMode::tangent);
  // Only one product given: that one, whatever it costs.
  CHECK(dpgen::jacobian(nullptr, vjp_small, x, 4, &mode) == by_rows);
  CHECK(mode == dpgen::JacobianMode::adjoint);
  CHECK(dpgen::jacobian(jvp_small, nullptr, x, 4, &mode) == by_columns);
  CHECK(mode == dpgen::JacobianMode::tangent);
}

TEST_CASE("jacobian: the cheaper mode counts products") {
  CHECK(dpgen::cheaper_jacobian_mode(3, 4) == dpgen::JacobianMode::tangent);
  CHECK(dpgen::cheaper_jacobian_mode(4, 4) == dpgen::JacobianMode::tangent);
  CHECK(dpgen::cheaper_jacobian_mode(5, 4) == dpgen::JacobianMode::adjoint);
  CHECK(std::string(dpgen::to_string(dpgen::JacobianMode::adjoint)) == "adjoint");

  // A scalar function of 5 inputs: one adjoint instead of five tangents.
  int tangents = 0, adjoints = 0;
  const dpgen::JacobianVectorProduct jvp = [&](const VectorXd& x, const VectorXd& v) {
    ++tangents;
    return VectorXd::Constant(1, x.cwiseProduct(v).sum());
  };
  const dpgen::VectorJacobianProduct vjp = [&](const VectorXd& x, const VectorXd& w) {
    ++adjoints;
    return VectorXd(w[0] * x);
  };
  const VectorXd x = dpgen_test::random_vector(5, 3);
  dpgen::JacobianMode mode = dpgen::JacobianMode::tangent;
  const MatrixXd j = dpgen::jacobian(jvp, vjp, x, 1, &mode);
  CHECK(mode == dpgen::JacobianMode::adjoint);
  CHECK(adjoints == 1);
  CHECK(tangents == 0);
  CHECK(j == x.transpose());
  CHECK(dpgen::jacobian_by_columns(jvp, x, 1) == j);
  CHECK(tangents == 5);
}

TEST_CASE("jacobian: generated upwind_step tangent and adjoint kernels") {
  const Upwind k;
  // d anywhere; u bounded away from 0, where min/max switch branch, in both directions.
  VectorXd x(2 * k.n);
  x.head(k.n) = dpgen_test::random_vector(k.n, 11);
  x.tail(k.n) = dpgen_test::random_vector(k.n, 12, 0.2, 1.0);
  for (int i = 0; i < k.n; i += 3)
    x[k.n + i] = -x[k.n + i];

  const dpgen::JacobianVectorProduct jvp = [&](const VectorXd& y, const VectorXd& v) {
    return k.jvp(y, v);
  };
  const dpgen::VectorJacobianProduct vjp = [&](const VectorXd& y, const VectorXd& w) {
    return k.vjp(y, w);
  };
  const MatrixXd by_columns = dpgen::jacobian_by_columns(jvp, x, k.n);
  const MatrixXd by_rows = dpgen::jacobian_by_rows(vjp, x, k.n);
  REQUIRE(by_columns.rows() == k.n);
  REQUIRE(by_columns.cols() == 2 * k.n);
  CHECK(max_abs(by_columns - by_rows) <= 1e-12);
  // d_next is bilinear in (d, u) on each branch: central differences are exact up to rounding,
  // eps |d_next| / h ~ 1e-11.
  const MatrixXd fd = dpgen::jacobian_central_difference([&](const VectorXd& y) { return k.forward(y); }, x);
  CHECK(max_abs(by_columns - fd) <= 1e-8);
  // Each row couples d[i-1], d[i], d[i+1] and u[i]: at most 4 nonzeros.
  for (Eigen::Index i = 0; i < k.n; ++i)
    CHECK((by_columns.row(i).array() != 0.0).count() <= 4);

  // 2n inputs > n outputs: n adjoints.
  dpgen::JacobianMode mode = dpgen::JacobianMode::tangent;
  CHECK(dpgen::jacobian(jvp, vjp, x, k.n, &mode) == by_rows);
  CHECK(mode == dpgen::JacobianMode::adjoint);
}

TEST_CASE("jacobian: size mismatches and missing products throw") {
  const VectorXd x = VectorXd::Ones(3);
  const auto message = [](const std::function<void()>& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  // jvp_small returns 4 entries where 5 outputs are claimed; short_vjp 2 for 3 inputs.
  CHECK(message([&] { dpgen::jacobian_by_columns(jvp_small, x, 5); }) ==
        "jacobian (tangent): Jacobian-vector product for input 0 has size 4, expected 5");
  const dpgen::VectorJacobianProduct short_vjp = [](const VectorXd&, const VectorXd&) {
    return VectorXd(VectorXd::Zero(2));
  };
  CHECK(message([&] { dpgen::jacobian_by_rows(short_vjp, x, 4); }) ==
        "jacobian (adjoint): vector-Jacobian product for output 0 has size 2, expected 3");
  CHECK(message([&] { dpgen::jacobian_by_columns(nullptr, x, 4); }) ==
        "jacobian (tangent): no Jacobian-vector product given");
  CHECK(message([&] { dpgen::jacobian_by_rows(nullptr, x, 4); }) ==
        "jacobian (adjoint): no vector-Jacobian product given");
  CHECK(message([&] { dpgen::jacobian(nullptr, nullptr, x, 4); }) ==
        "jacobian: neither a Jacobian-vector nor a vector-Jacobian product given");
  CHECK(message([&] { dpgen::jacobian(jvp_small, vjp_small, x, -1); }) ==
        "jacobian: sizes must be >= 0 (got 3 inputs, -1 outputs)");
  CHECK(message([&] { dpgen::jacobian_central_difference(f_small, x, 0.0); }) ==
        "jacobian (central differences): step must be positive (got 0)");
  CHECK(message([&] { dpgen::jacobian_central_difference(nullptr, x); }) ==
        "jacobian (central differences): no function given");
  // An f whose output size depends on x: 4 entries at x, 3 once x_1 moves.
  const auto ragged = [](const VectorXd& v) {
    return VectorXd(VectorXd::Zero(v[1] == 1.0 ? 4 : 3));
  };
  CHECK(message([&] { dpgen::jacobian_central_difference(ragged, x); }) ==
        "jacobian (central differences): f(x + h e_1) has size 3, expected 4");
}

TEST_CASE("jacobian_central_difference: exact on quadratics up to rounding, steps scale with x") {
  // Central differences have no truncation error on a quadratic: only rounding, eps |f| / h.
  const auto quadratic = [](const VectorXd& v) {
    return VectorXd((VectorXd(2) << v[0] * v[0] - 3.0 * v[1], v[0] * v[1]).finished());
  };
  const VectorXd x = (VectorXd(2) << 2.0, -1e4).finished();
  MatrixXd exact(2, 2);
  exact << 2.0 * x[0], -3.0, x[1], x[0];
  CHECK(max_abs(dpgen::jacobian_central_difference(quadratic, x) - exact) <= 1e-6);
  // On a cubic the error is h^2 f''' / 6 = h^2 with h = step (1 + |x|): step 1e-2 at x = 1
  // gives h = 0.02 and an error of 4e-4 (a step not scaled by 1 + |x| would give 1e-4).
  const auto cubic = [](const VectorXd& v) {
    return VectorXd(VectorXd::Constant(1, v[0] * v[0] * v[0]));
  };
  const MatrixXd j = dpgen::jacobian_central_difference(cubic, VectorXd::Ones(1), 1e-2);
  CHECK(j(0, 0) - 3.0 == doctest::Approx(4e-4).epsilon(1e-6));
}
