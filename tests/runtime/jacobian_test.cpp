// Tests of dpgen/jacobian.hpp: columns (JVPs) and rows (VJPs) agree with each other and with
// central differences, on a small nonlinear map and on a rollout of the generated upwind
// adjoint; the automatic mode takes the one needing fewer products; bad input is an error.
#include "dpgen/jacobian.hpp"
#include "kernels.hpp"
#include "upwind_step_adjoint.hpp"

#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using dpgen::JacobianMode;
using dpgen_test::random_vector;

// f: R^3 -> R^5, f = (x0 x1, sin x2, x0^2, x1 exp(x2), x0 + x1 + x2), with its JVP and VJP
// written out by hand.
VectorXd f(const VectorXd& x) {
  VectorXd y(5);
  y << x[0] * x[1], std::sin(x[2]), x[0] * x[0], x[1] * std::exp(x[2]), x.sum();
  return y;
}
MatrixXd f_jacobian(const VectorXd& x) {
  MatrixXd j(5, 3);
  const double e = std::exp(x[2]);
  j << x[1], x[0], 0, //
      0, 0, std::cos(x[2]), //
      2 * x[0], 0, 0, //
      0, e, x[1] * e, //
      1, 1, 1;
  return j;
}

// The largest entry of |a - b| relative to max(1, |b|_max).
double relative_difference(const MatrixXd& a, const MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

TEST_CASE("columns and rows give the same Jacobian, which central differences confirm") {
  const VectorXd x = random_vector(3, 1);
  const MatrixXd j_exact = f_jacobian(x);
  const auto jvp = [&](const VectorXd& v) -> VectorXd { return f_jacobian(x) * v; };
  const auto vjp = [&](const VectorXd& w) -> VectorXd { return f_jacobian(x).transpose() * w; };
  dpgen::JacobianSummary by_columns, by_rows;
  const MatrixXd jc = dpgen::jacobian(5, 3, jvp, vjp, JacobianMode::columns, &by_columns);
  const MatrixXd jr = dpgen::jacobian(5, 3, jvp, vjp, JacobianMode::rows, &by_rows);
  CHECK(by_columns.products == 3);
  CHECK(by_rows.products == 5);
  CHECK(relative_difference(jc, jr) < 1e-15);
  // Central differences with h = 1e-6: truncation h^2 |f'''| ~ 1e-12, rounding eps/h ~ 1e-10.
  const MatrixXd jfd = dpgen::jacobian_central_difference(f, x);
  CHECK(relative_difference(jc, jfd) < 1e-8);
  CHECK(relative_difference(jc, j_exact) < 1e-15);
}

TEST_CASE("the automatic mode takes the product needing fewer calls, or the only one given") {
  int jvps = 0, vjps = 0;
  const MatrixXd a = MatrixXd::Random(2, 6);
  const auto jvp = [&](const VectorXd& v) -> VectorXd {
    ++jvps;
    return a * v;
  };
  const auto vjp = [&](const VectorXd& w) -> VectorXd {
    ++vjps;
    return a.transpose() * w;
  };
  dpgen::JacobianSummary s;
  CHECK(relative_difference(dpgen::jacobian(2, 6, jvp, vjp, JacobianMode::automatic, &s), a) <
        1e-15);
  CHECK(s.mode == JacobianMode::rows);
  CHECK((jvps == 0 && vjps == 2));
  const MatrixXd at = a.transpose(); // 6 outputs, 2 inputs: columns are cheaper
  const auto jvp_t = [&](const VectorXd& v) -> VectorXd { return at * v; };
  CHECK(relative_difference(dpgen::jacobian(6, 2, jvp_t, nullptr, JacobianMode::automatic, &s),
                            at) < 1e-15);
  CHECK(s.mode == JacobianMode::columns);
  CHECK(s.products == 2);
  CHECK(dpgen::resolve_jacobian_mode(6, 2, false, true) == JacobianMode::rows); // only a VJP
  CHECK(dpgen::resolve_jacobian_mode(3, 3, true, true) == JacobianMode::columns); // a tie
}

// d_T = U(u)^T d_0 with the upwind step as the kernel; fixed u, so d_T is linear in d_0 and
// its JVP is the rollout of the tangent itself. The VJP runs the generated adjoint backwards.
struct UpwindRollout {
  int n = 12, steps = 6;
  double dt = 0.02, dx = 1.0 / 12;
  VectorXd u = random_vector(12, 3, -1.0, 1.0);
  VectorXd run(const VectorXd& d0) const {
    VectorXd d = d0, next(n);
    for (int s = 0; s < steps; ++s) {
      upwind_step(d.data(), u.data(), next.data(), n, dt, dx);
      d.swap(next);
    }
    return d;
  }
  VectorXd adjoint(const VectorXd& w) const {
    VectorXd g = w, g_prev(n), u_adj(n);
    const VectorXd d_unused = VectorXd::Zero(n); // linear in d: the adjoint does not read d
    for (int s = 0; s < steps; ++s) {
      g_prev.setZero();
      u_adj.setZero();
      upwind_step_adjoint(d_unused.data(), g_prev.data(), u.data(), u_adj.data(), g.data(), n,
                          dt, dx);
      g.swap(g_prev);
    }
    return g;
  }
};

TEST_CASE("Jacobian of a rollout of the generated upwind adjoint: rows, columns, differences") {
  const UpwindRollout r;
  const auto jvp = [&](const VectorXd& v) { return r.run(v); };
  const auto vjp = [&](const VectorXd& w) { return r.adjoint(w); };
  const MatrixXd jr = dpgen::jacobian(r.n, r.n, jvp, vjp, JacobianMode::rows);
  const MatrixXd jc = dpgen::jacobian(r.n, r.n, jvp, vjp, JacobianMode::columns);
  const MatrixXd jfd =
      dpgen::jacobian_central_difference([&](const VectorXd& d) { return r.run(d); },
                                         random_vector(r.n, 5));
  CHECK(relative_difference(jr, jc) < 1e-13);
  CHECK(relative_difference(jr, jfd) < 1e-8);
  CHECK(jr.norm() > 1.0); // not trivially zero
}

TEST_CASE("bad input is a clear error") {
  const auto jvp = [](const VectorXd&) -> VectorXd { return VectorXd::Zero(4); };
  const auto vjp_bad = [](const VectorXd& w) -> VectorXd {
    return w[2] == 1.0 ? VectorXd::Zero(2) : VectorXd::Zero(3);
  };
  CHECK_THROWS_WITH_AS(dpgen::jacobian(3, 3, nullptr, vjp_bad, JacobianMode::rows),
                       "jacobian: VJP of output 2 has size 2, expected 3", std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::jacobian(3, 3, jvp, nullptr), "jacobian: JVP of input 0 has size 4, "
                                                            "expected 3",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::jacobian(3, 3, jvp, nullptr, JacobianMode::rows),
                       "jacobian: mode 'rows' needs a VJP, none was given", std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::jacobian(3, 3, nullptr, nullptr),
                       "jacobian: neither a JVP nor a VJP was given", std::invalid_argument);
  CHECK_THROWS_WITH_AS(dpgen::jacobian(0, 3, jvp, nullptr),
                       "jacobian: sizes must be positive (got 0 outputs, 3 inputs)",
                       std::invalid_argument);
  const auto jvp_nan = [](const VectorXd& v) -> VectorXd { return v * std::nan(""); };
  CHECK_THROWS_WITH_AS(dpgen::jacobian(3, 3, jvp_nan, nullptr),
                       "jacobian: JVP of input 0 contains nan at index 0", std::invalid_argument);
}

} // namespace
