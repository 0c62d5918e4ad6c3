// Tests of dpgen/cg.hpp: the matrix-free CG against Eigen's ConjugateGradient and a direct
// solve on an explicit sparse SPD matrix, preconditioning, null spaces, and every error path.
#include "dpgen/cg.hpp"

#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using dpgen::detail::format_number;
using Eigen::VectorXd;

using dpgen_test::random_vector;

// -div(k grad p) on an nx-by-ny cell grid with zero Dirichlet values outside, k at cell
// centres averaged arithmetically onto faces: SPD for k > 0. Written as a stencil (the way a
// kernel computes it) ...
struct Poisson2d {
  int nx, ny;
  VectorXd k;

  double face(int a, int b) const { return 0.5 * (k[a] + k[b]); }

  void apply(const VectorXd& p, VectorXd& out) const {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c = j * nx + i;
        double sum = 0.0;
        // Neighbours outside the grid are Dirichlet zeros with face coefficient k[c].
        sum += (i > 0 ? face(c, c - 1) : k[c]) * (p[c] - (i > 0 ? p[c - 1] : 0.0));
        sum += (i < nx - 1 ? face(c, c + 1) : k[c]) * (p[c] - (i < nx - 1 ? p[c + 1] : 0.0));
        sum += (j > 0 ? face(c, c - nx) : k[c]) * (p[c] - (j > 0 ? p[c - nx] : 0.0));
        sum += (j < ny - 1 ? face(c, c + nx) : k[c]) * (p[c] - (j < ny - 1 ? p[c + nx] : 0.0));
        out[c] = sum;
      }
  }

  // ... and assembled as an explicit sparse matrix for the oracles.
  Eigen::SparseMatrix<double> matrix() const {
    std::vector<Eigen::Triplet<double>> entries;
    const int n = nx * ny;
    for (int c = 0; c < n; ++c) {
      VectorXd e = VectorXd::Zero(n);
      e[c] = 1.0;
      VectorXd column(n);
      apply(e, column);
      for (int r = 0; r < n; ++r)
        if (column[r] != 0.0)
          entries.emplace_back(r, c, column[r]);
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    return a;
  }
};

Poisson2d make_poisson(int nx, int ny, unsigned seed) {
  return Poisson2d{nx, ny, random_vector(nx * ny, seed, 0.5, 2.0)};
}

} // namespace

TEST_CASE("cg matches Eigen's ConjugateGradient and a direct solve on a sparse SPD matrix") {
  const Poisson2d poisson = make_poisson(16, 12, 1);
  const Eigen::SparseMatrix<double> a = poisson.matrix();
  REQUIRE(a.isApprox(Eigen::SparseMatrix<double>(a.transpose()))); // the oracle is symmetric
  const VectorXd b = random_vector(a.rows(), 2);

  dpgen::CgOptions options;
  options.relative_tolerance = 1e-10;
  VectorXd x;
  const dpgen::CgSummary summary = dpgen::conjugate_gradient(
      [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); }, b, x, options);
  CHECK(summary.converged());
  CHECK(summary.final_residual_norm <= 1e-10 * b.norm());
  CHECK(summary.initial_residual_norm == doctest::Approx(b.norm()).epsilon(1e-15));
  CHECK((b - a * x).norm() <= 2e-10 * b.norm()); // the recursive residual is the true one

  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::IdentityPreconditioner>
      eigen_cg(a);
  eigen_cg.setTolerance(1e-10);
  const VectorXd x_eigen = eigen_cg.solve(b);
  REQUIRE(eigen_cg.info() == Eigen::Success);
  // Same algorithm, same stopping rule (Eigen stops at ||r|| < tol ||b||, we at <=).
  CHECK(std::abs(summary.iterations - static_cast<int>(eigen_cg.iterations())) <= 1);

  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(a);
  const VectorXd x_direct = direct.solve(b);
  // Both iterative solutions are within cond(A) * tol of the direct one; cond(A) < 1e3 here.
  CHECK((x - x_direct).norm() <= 1e3 * 1e-10 * x_direct.norm());
  CHECK((x - x_eigen).norm() <= 1e3 * 1e-10 * x_direct.norm());
}

TEST_CASE("cg: Jacobi preconditioning matches Eigen's DiagonalPreconditioner") {
  Poisson2d poisson = make_poisson(10, 10, 3);
  // Coefficients spanning four decades make the diagonal badly scaled.
  for (Eigen::Index c = 0; c < poisson.k.size(); ++c)
    poisson.k[c] = std::pow(10.0, 4.0 * (poisson.k[c] - 0.5) / 1.5);
  const Eigen::SparseMatrix<double> a = poisson.matrix();
  const VectorXd b = random_vector(a.rows(), 4);
  const auto apply = [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); };

  dpgen::CgOptions plain;
  plain.max_iterations = 5000;
  VectorXd x_plain;
  const dpgen::CgSummary s_plain = dpgen::conjugate_gradient(apply, b, x_plain, plain);

  dpgen::CgOptions jacobi = plain;
  jacobi.jacobi_diagonal = a.diagonal();
  VectorXd x_jacobi;
  const dpgen::CgSummary s_jacobi = dpgen::conjugate_gradient(apply, b, x_jacobi, jacobi);
  CHECK(s_jacobi.converged());
  CHECK(s_jacobi.iterations < s_plain.iterations);

  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> eigen_cg(a);
  eigen_cg.setTolerance(1e-10);
  eigen_cg.setMaxIterations(5000);
  const VectorXd x_eigen = eigen_cg.solve(b);
  REQUIRE(eigen_cg.info() == Eigen::Success);
  CHECK(std::abs(s_jacobi.iterations - static_cast<int>(eigen_cg.iterations())) <= 1);
  const VectorXd x_direct = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(a).solve(b);
  CHECK((x_jacobi - x_direct).norm() <= 1e-5 * x_direct.norm());
  CHECK((x_eigen - x_direct).norm() <= 1e-5 * x_direct.norm());
}

TEST_CASE("cg: a general preconditioner callable and the initial guess") {
  const Poisson2d poisson = make_poisson(8, 8, 5);
  const Eigen::SparseMatrix<double> a = poisson.matrix();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(a);
  const VectorXd b = random_vector(a.rows(), 6);
  const auto apply = [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); };

  // M = A: the preconditioned system is the identity, so one iteration solves it.
  dpgen::CgOptions exact;
  exact.preconditioner = [&](const VectorXd& r, VectorXd& z) { z = direct.solve(r); };
  VectorXd x;
  CHECK(dpgen::conjugate_gradient(apply, b, x, exact).iterations == 1);
  CHECK((x - direct.solve(b)).norm() <= 1e-12 * x.norm());

  VectorXd x0 = direct.solve(b); // already the solution: no iteration needed
  CHECK(dpgen::conjugate_gradient(apply, b, x0, {}, &x0).iterations == 0);

  VectorXd x_cold;
  const int cold_iterations = dpgen::conjugate_gradient(apply, b, x_cold).iterations;
  VectorXd x_near = direct.solve(b) + 1e-6 * random_vector(b.size(), 7);
  const dpgen::CgSummary near = dpgen::conjugate_gradient(apply, b, x_near, {}, &x_near);
  CHECK(near.converged());
  CHECK(near.iterations < cold_iterations);
  CHECK(near.initial_residual_norm < 1e-4 * b.norm());
}

TEST_CASE("cg: a zero right-hand side gives the zero solution without iterating") {
  const Poisson2d poisson = make_poisson(4, 4, 8);
  VectorXd x = VectorXd::Ones(16);
  const dpgen::CgSummary summary = dpgen::conjugate_gradient(
      [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); }, VectorXd::Zero(16), x);
  CHECK(summary.converged());
  CHECK(summary.iterations == 0);
  CHECK(x.isZero(0.0));
}

TEST_CASE("cg: periodic Poisson with null-space mean removal") {
  // -d^2/dx^2 on a periodic grid: symmetric positive semi-definite, null space = constants.
  constexpr int n = 64;
  const auto apply = [](const VectorXd& v, VectorXd& y) {
    for (int i = 0; i < n; ++i)
      y[i] = 2.0 * v[i] - v[(i + 1) % n] - v[(i + n - 1) % n];
  };
  VectorXd b = random_vector(n, 9);
  b.array() += 0.7; // a mean the operator cannot produce
  dpgen::CgOptions options;
  options.remove_null_space_mean = true;
  VectorXd x;
  const dpgen::CgSummary summary = dpgen::conjugate_gradient(apply, b, x, options);
  CHECK(summary.converged());
  CHECK(std::abs(x.mean()) <= 1e-14 * x.norm());
  VectorXd ax(n);
  apply(x, ax);
  const VectorXd pb = b.array() - b.mean();
  CHECK((ax - pb).norm() <= 2e-10 * pb.norm());

  // Without the option the constant part of the residual can never be removed.
  dpgen::CgOptions plain;
  plain.max_iterations = 200;
  VectorXd x_plain;
  CHECK_THROWS_AS(dpgen::conjugate_gradient(apply, b, x_plain, plain), dpgen::SolveError);
}

TEST_CASE("cg: non-convergence is an error with iterations and residual") {
  const Poisson2d poisson = make_poisson(16, 16, 10);
  const auto apply = [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); };
  const VectorXd b = random_vector(256, 11);
  dpgen::CgOptions options;
  options.max_iterations = 5;
  VectorXd x;
  try {
    dpgen::conjugate_gradient(apply, b, x, options);
    FAIL("expected a SolveError");
  } catch (const dpgen::SolveError& e) {
    const dpgen::CgSummary& s = e.summary();
    CHECK(s.termination == dpgen::CgTermination::max_iterations);
    CHECK(s.iterations == 5);
    CHECK(s.final_residual_norm > s.tolerance);
    CHECK(std::string(e.what()) == "cg: did not converge after 5 iterations, residual " +
                                       format_number(s.final_residual_norm) + " > tolerance " +
                                       format_number(s.tolerance));
  }
  // With throw_on_failure off, the same failure is only reported.
  options.throw_on_failure = false;
  const dpgen::CgSummary s = dpgen::conjugate_gradient(apply, b, x, options);
  CHECK_FALSE(s.converged());
  CHECK(s.message.find("did not converge after 5 iterations") != std::string::npos);
}

TEST_CASE("cg: a negative definite or indefinite operator is detected by negative curvature") {
  const Poisson2d poisson = make_poisson(6, 6, 12);
  const VectorXd b = random_vector(36, 13);
  VectorXd x;
  // The Laplacian itself (not its negation) is negative definite: caught at iteration 1.
  const auto laplacian = [&](const VectorXd& v, VectorXd& y) {
    poisson.apply(v, y);
    y = -y;
  };
  try {
    dpgen::conjugate_gradient(laplacian, b, x);
    FAIL("expected a SolveError");
  } catch (const dpgen::SolveError& e) {
    CHECK(e.summary().termination == dpgen::CgTermination::negative_curvature);
    CHECK(e.summary().iterations == 1);
    const std::string what = e.what();
    CHECK(what.rfind("cg: operator is not symmetric positive definite: p^T A p = -", 0) == 0);
    CHECK(what.find("<= 0 at iteration 1") != std::string::npos);
  }
  // Indefinite: diag(1, ..., 1, -1) with b touching both signs.
  const auto indefinite = [](const VectorXd& v, VectorXd& y) {
    y = v;
    y[y.size() - 1] = -v[v.size() - 1];
  };
  dpgen::CgOptions options;
  options.throw_on_failure = false;
  const dpgen::CgSummary s = dpgen::conjugate_gradient(indefinite, VectorXd::Ones(4), x, options);
  CHECK(s.termination == dpgen::CgTermination::negative_curvature);
}

TEST_CASE("cg: NaN input and NaN operator output") {
  const auto identity = [](const VectorXd& v, VectorXd& y) { y = v; };
  VectorXd b = VectorXd::Ones(5);
  b[3] = std::numeric_limits<double>::quiet_NaN();
  VectorXd x;
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(identity, b, x),
                       "cg: right-hand side b contains nan at index 3", std::invalid_argument);

  VectorXd x0 = VectorXd::Ones(5);
  x0[1] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(identity, VectorXd::Ones(5), x, {}, &x0),
                       "cg: initial guess contains inf at index 1", std::invalid_argument);

  const auto poisoned = [](const VectorXd& v, VectorXd& y) {
    y = v;
    y[2] = std::numeric_limits<double>::quiet_NaN();
  };
  try {
    dpgen::conjugate_gradient(poisoned, VectorXd::Ones(5), x);
    FAIL("expected a SolveError");
  } catch (const dpgen::SolveError& e) {
    CHECK(e.summary().termination == dpgen::CgTermination::nan);
    CHECK(std::string(e.what()) == "cg: NaN or Inf appeared at iteration 1 (operator or "
                                   "preconditioner output is not finite)");
  }
}

TEST_CASE("cg: size mismatches name both sizes") {
  VectorXd x;
  const auto shrinking = [](const VectorXd& v, VectorXd& y) { y = v.head(v.size() - 1); };
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(shrinking, VectorXd::Ones(8), x),
                       "cg: operator returned a vector of size 7 for an input of size 8",
                       std::invalid_argument);

  // A raw-pointer kernel on 64 cells given a 100-value field refuses instead of overrunning.
  const dpgen::VectorOperator kernel = dpgen::kernel_operator(
      64,
      [](const double* in, double* out) {
        for (int i = 0; i < 64; ++i)
          out[i] = 2.0 * in[i];
      },
      "laplacian2d");
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(kernel, VectorXd::Ones(100), x),
                       "laplacian2d: field of size 100 passed to an operator on 64 cells",
                       std::invalid_argument);
  const dpgen::CgSummary ok = dpgen::conjugate_gradient(kernel, VectorXd::Ones(64), x);
  CHECK(ok.converged());
  CHECK(x.isApproxToConstant(0.5, 1e-14));

  VectorXd x0 = VectorXd::Zero(3);
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(kernel, VectorXd::Ones(64), x0, {}, &x0),
                       "cg: initial guess has size 3, expected 64", std::invalid_argument);

  dpgen::CgOptions jacobi;
  jacobi.jacobi_diagonal = VectorXd::Ones(10);
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(kernel, VectorXd::Ones(64), x, jacobi),
                       "cg: jacobi_diagonal has size 10, expected 64", std::invalid_argument);
}

TEST_CASE("cg: invalid options are rejected") {
  const auto identity = [](const VectorXd& v, VectorXd& y) { y = v; };
  VectorXd x;
  dpgen::CgOptions both;
  both.jacobi_diagonal = VectorXd::Ones(3);
  both.preconditioner = identity;
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(identity, VectorXd::Ones(3), x, both),
                       "cg: set either jacobi_diagonal or preconditioner, not both",
                       std::invalid_argument);
  dpgen::CgOptions bad_diagonal;
  bad_diagonal.jacobi_diagonal = VectorXd::Ones(3);
  bad_diagonal.jacobi_diagonal[1] = -2.0;
  CHECK_THROWS_WITH_AS(dpgen::conjugate_gradient(identity, VectorXd::Ones(3), x, bad_diagonal),
                       "cg: jacobi_diagonal[1] = -2 is not a positive finite number",
                       std::invalid_argument);
  dpgen::CgOptions negative;
  negative.max_iterations = -1;
  CHECK_THROWS_AS(dpgen::conjugate_gradient(identity, VectorXd::Ones(3), x, negative),
                  std::invalid_argument);
}

TEST_CASE("cg: the initial guess is the initial_guess argument, never x's old contents") {
  const Poisson2d poisson = make_poisson(8, 8, 11);
  const Eigen::SparseMatrix<double> a = poisson.matrix();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(a);
  const VectorXd b = random_vector(a.rows(), 12);
  const auto apply = [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); };
  const VectorXd solution = direct.solve(b);

  // Started at the solution (a separate vector, or x itself): 0 iterations, x unchanged.
  VectorXd x;
  const dpgen::CgSummary from_solution = dpgen::conjugate_gradient(apply, b, x, {}, &solution);
  CHECK(from_solution.iterations == 0);
  CHECK(from_solution.converged());
  CHECK(x == solution);
  VectorXd in_place = solution;
  CHECK(dpgen::conjugate_gradient(apply, b, in_place, {}, &in_place).iterations == 0);
  CHECK(in_place == solution);

  // Without the argument, x holding the solution is ignored: the solve starts from zero and
  // gives the same bits as one into an empty vector.
  VectorXd ignored = solution, fresh;
  const dpgen::CgSummary cold = dpgen::conjugate_gradient(apply, b, ignored);
  const dpgen::CgSummary cold_fresh = dpgen::conjugate_gradient(apply, b, fresh);
  CHECK(cold.iterations > 0);
  CHECK(cold.iterations == cold_fresh.iterations);
  CHECK(cold.initial_residual_norm == b.norm());
  CHECK(ignored == fresh);
}

TEST_CASE("cg: a workspace gives bit-identical results and is not reallocated") {
  const Poisson2d poisson = make_poisson(12, 10, 13);
  const auto apply = [&](const VectorXd& v, VectorXd& y) { poisson.apply(v, y); };
  const VectorXd b1 = random_vector(120, 14), b2 = random_vector(120, 15);
  for (const bool jacobi : {false, true}) {
    CAPTURE(jacobi);
    dpgen::CgOptions plain;
    plain.relative_tolerance = 1e-12;
    if (jacobi)
      plain.jacobi_diagonal = poisson.matrix().diagonal();
    dpgen::CgWorkspace workspace;
    dpgen::CgOptions reused = plain;
    reused.workspace = &workspace;

    VectorXd x_plain, x_reused;
    const dpgen::CgSummary s_plain = dpgen::conjugate_gradient(apply, b1, x_plain, plain);
    const dpgen::CgSummary s_reused = dpgen::conjugate_gradient(apply, b1, x_reused, reused);
    CHECK(s_plain.iterations == s_reused.iterations);
    CHECK(s_plain.final_residual_norm == s_reused.final_residual_norm);
    REQUIRE(x_reused.size() == x_plain.size());
    CHECK(x_reused == x_plain); // bit for bit
    REQUIRE(workspace.r.size() == 120);
    REQUIRE(workspace.z.size() == 120);
    REQUIRE(workspace.p.size() == 120);
    REQUIRE(workspace.q.size() == 120);
    const double* r = workspace.r.data();
    const double* z = workspace.z.data();
    const double* p = workspace.p.data();
    const double* q = workspace.q.data();
    const double* x = x_reused.data();

    // A second solve (another right-hand side, warm-started from x) reuses every buffer.
    const dpgen::CgSummary second =
        dpgen::conjugate_gradient(apply, b2, x_reused, reused, &x_reused);
    CHECK(second.converged());
    CHECK(workspace.r.data() == r);
    CHECK(workspace.z.data() == z);
    CHECK(workspace.p.data() == p);
    CHECK(workspace.q.data() == q);
    CHECK(x_reused.data() == x);
    VectorXd x2_plain = x_plain;
    dpgen::conjugate_gradient(apply, b2, x2_plain, plain, &x2_plain);
    CHECK(x_reused == x2_plain);
  }
}
