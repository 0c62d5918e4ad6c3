// Tests of dpgen/implicit_solve.hpp: gradients of x = A(k)^-1 b for a variable-coefficient
// Poisson operator against finite differences of the whole solve and against differentiating
// through the unrolled CG iterations; periodic (null space) and non-symmetric cases; errors.
#include "dpgen/implicit_solve.hpp"
#include "neg_div_k_grad_1d_adjoint.hpp"
#include "neg_div_k_grad_periodic2d_adjoint.hpp"
#include "operators.hpp"

#include "test_support.hpp"

#include <doctest/doctest.h>

#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;

using dpgen_test::random_vector;

// The operators are dpgen kernels (tests/runtime/operators/); their adjoints,
// in particular w.r.t. the coefficient k that theta_bar needs, are generated
// at build time.
// Upwind advection (velocity c > 0) plus a shift, added to the 1D operator to make it
// non-symmetric: (D p)_i = c (p_i - p_{i-1}) / h + sigma p_i; D^T q_i = c (q_i - q_{i+1}) / h
// + sigma q_i (zero ghosts).
struct Advection {
  int n;
  double c, h, sigma;
  void apply(const VectorXd& p, VectorXd& out) const {
    for (int i = 0; i < n; ++i)
      out[i] += c * (p[i] - (i > 0 ? p[i - 1] : 0.0)) / h + sigma * p[i];
  }
  void apply_transpose(const VectorXd& q, VectorXd& out) const {
    for (int i = 0; i < n; ++i)
      out[i] += c * (q[i] - (i < n - 1 ? q[i + 1] : 0.0)) / h + sigma * q[i];
  }
};

// The 1D problem: n cells on (0, 1), coefficient k on the faces.
struct Problem1d {
  int n = 32;
  double h = 1.0 / 33.0;
  VectorXd k = random_vector(33, 21, 0.5, 2.0);

  void apply(const VectorXd& k_, const VectorXd& p, VectorXd& out) const {
    out.resize(n);
    neg_div_k_grad_1d(p.data(), k_.data(), out.data(), n, h);
  }
  // (d(A(k) x)/dk)^T lambda, accumulated into g: the kernel adjoint seeded with lambda.
  void adjoint_k(const VectorXd& x, const VectorXd& lambda, VectorXd& g) const {
    VectorXd x_adj = VectorXd::Zero(n); // not needed here
    neg_div_k_grad_1d_adjoint(x.data(), x_adj.data(), k.data(), g.data(), lambda.data(), n, h);
  }
};

// L(x) = 1/2 |x - target|^2, so x_bar = x - target.
double loss(const VectorXd& x, const VectorXd& target) { return 0.5 * (x - target).squaredNorm(); }

// Central differences of f along every coordinate of v, with step eps.
template <typename F> VectorXd central_differences(F&& f, VectorXd v, double eps) {
  VectorXd grad(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double saved = v[i];
    v[i] = saved + eps;
    const double up = f(v);
    v[i] = saved - eps;
    const double down = f(v);
    v[i] = saved;
    grad[i] = (up - down) / (2.0 * eps);
  }
  return grad;
}

double relative_error(const VectorXd& a, const VectorXd& b) { return (a - b).norm() / b.norm(); }

// Reference: plain CG (no preconditioner, x0 = 0) unrolled for a fixed number of iterations
// with every iterate recorded, then differentiated in reverse through all of them.
struct CgTape {
  std::vector<VectorXd> p, q, r_next; // p_i, q_i = A p_i, r_{i+1}
  std::vector<double> rr, pq, alpha, beta;
};

template <typename Apply>
VectorXd unrolled_cg(Apply&& apply, const VectorXd& b, int iterations, CgTape& tape) {
  VectorXd x = VectorXd::Zero(b.size()), r = b, p = b, q(b.size());
  double rr = b.dot(b);
  for (int i = 0; i < iterations; ++i) {
    apply(p, q);
    const double pq = p.dot(q), alpha = rr / pq;
    x += alpha * p;
    r -= alpha * q;
    const double rr_next = r.dot(r), beta = rr_next / rr;
    tape.p.push_back(p);
    tape.q.push_back(q);
    tape.r_next.push_back(r);
    tape.rr.push_back(rr);
    tape.pq.push_back(pq);
    tape.alpha.push_back(alpha);
    tape.beta.push_back(beta);
    p = r + beta * p;
    rr = rr_next;
  }
  tape.rr.push_back(rr);
  return x;
}

// Reverse sweep through the recorded iterations; `apply` is A (= A^T), `adjoint_k(p, q_bar, g)`
// adds (d(A(k) p)/dk)^T q_bar into g.
template <typename Apply, typename AdjointK>
void unrolled_cg_backward(Apply&& apply, AdjointK&& adjoint_k, const CgTape& tape,
                          const VectorXd& b, const VectorXd& x_bar, VectorXd& b_bar,
                          VectorXd& k_bar) {
  const Eigen::Index n = b.size();
  VectorXd p_bar = VectorXd::Zero(n), r_bar = VectorXd::Zero(n), a_q(n);
  double rr_bar = 0.0; // adjoint of rr_{i+1}
  for (int i = static_cast<int>(tape.p.size()) - 1; i >= 0; --i) {
    const VectorXd& p = tape.p[i];
    const VectorXd& q = tape.q[i];
    // p_{i+1} = r_{i+1} + beta_i p_i
    r_bar += p_bar;
    const double beta_bar = p_bar.dot(p);
    VectorXd p_bar_i = tape.beta[i] * p_bar;
    // beta_i = rr_{i+1} / rr_i
    rr_bar += beta_bar / tape.rr[i];
    double rr_bar_i = -beta_bar * tape.rr[i + 1] / (tape.rr[i] * tape.rr[i]);
    // rr_{i+1} = r_{i+1} . r_{i+1}
    r_bar += 2.0 * rr_bar * tape.r_next[i];
    // r_{i+1} = r_i - alpha_i q_i   (r_bar carries over to r_i)
    double alpha_bar = -r_bar.dot(q);
    VectorXd q_bar = -tape.alpha[i] * r_bar;
    // x_{i+1} = x_i + alpha_i p_i   (x_bar carries over unchanged)
    alpha_bar += x_bar.dot(p);
    p_bar_i += tape.alpha[i] * x_bar;
    // alpha_i = rr_i / pq_i
    rr_bar_i += alpha_bar / tape.pq[i];
    const double pq_bar = -alpha_bar * tape.rr[i] / (tape.pq[i] * tape.pq[i]);
    // pq_i = p_i . q_i
    p_bar_i += pq_bar * q;
    q_bar += pq_bar * p;
    // q_i = A(k) p_i
    apply(q_bar, a_q);
    p_bar_i += a_q;
    adjoint_k(p, q_bar, k_bar);
    p_bar = p_bar_i;
    rr_bar = rr_bar_i;
  }
  // r_0 = b, p_0 = b, rr_0 = b . b
  b_bar += r_bar + p_bar + 2.0 * rr_bar * b;
}

} // namespace

TEST_CASE("the generated operator adjoints pass the dot-product test") {
  // <J v, w> == <v, J^T w> for the Jacobian w.r.t. k (the operator is linear in k).
  const Problem1d pr;
  const VectorXd x = random_vector(pr.n, 22), dk = random_vector(pr.n + 1, 23);
  const VectorXd w = random_vector(pr.n, 24);
  VectorXd jv;
  pr.apply(dk, x, jv);
  VectorXd jtw = VectorXd::Zero(pr.n + 1);
  pr.adjoint_k(x, w, jtw);
  CHECK(jv.dot(w) == doctest::Approx(dk.dot(jtw)).epsilon(1e-12));

  const int nx = 6, ny = 5;
  const VectorXd k = random_vector(nx * ny, 25, 0.5, 2.0), p = random_vector(nx * ny, 26);
  const VectorXd v = random_vector(nx * ny, 27), s = random_vector(nx * ny, 28);
  VectorXd jk(nx * ny), jp(nx * ny);
  neg_div_k_grad_periodic2d(p.data(), v.data(), jk.data(), nx, ny, 0.1); // J_k v
  neg_div_k_grad_periodic2d(v.data(), k.data(), jp.data(), nx, ny, 0.1); // J_p v
  VectorXd p_adj = VectorXd::Zero(nx * ny), k_adj = VectorXd::Zero(nx * ny);
  neg_div_k_grad_periodic2d_adjoint(p.data(), p_adj.data(), k.data(), k_adj.data(), s.data(), nx,
                                    ny, 0.1);
  CHECK(jk.dot(s) == doctest::Approx(v.dot(k_adj)).epsilon(1e-12));
  CHECK(jp.dot(s) == doctest::Approx(v.dot(p_adj)).epsilon(1e-12));

  const Advection adv{pr.n, 3.0, pr.h, 5.0};
  VectorXd dv = VectorXd::Zero(pr.n), dtw = VectorXd::Zero(pr.n);
  adv.apply(x, dv);
  adv.apply_transpose(w, dtw);
  CHECK(dv.dot(w) == doctest::Approx(x.dot(dtw)).epsilon(1e-12));
}

TEST_CASE("implicit gradients w.r.t. b and k match central differences of the whole solve") {
  const Problem1d pr;
  const VectorXd b = random_vector(pr.n, 31), target = random_vector(pr.n, 32, -0.01, 0.01);
  dpgen::CgOptions options;
  options.relative_tolerance = 1e-13;

  const auto solve = [&](const VectorXd& k, const VectorXd& rhs) {
    return dpgen::solve_forward([&](const VectorXd& v, VectorXd& y) { pr.apply(k, v, y); }, rhs,
                                options)
        .solution;
  };
  const auto apply = [&](const VectorXd& v, VectorXd& y) { pr.apply(pr.k, v, y); };
  const dpgen::LinearSolveResult forward = dpgen::solve_forward(apply, b, options);
  REQUIRE(forward.summary.converged());
  const VectorXd& x = forward.solution;

  VectorXd b_bar, k_bar = VectorXd::Zero(pr.n + 1);
  int adjoint_calls = 0, transpose_applications = 0;
  const dpgen::LinearSolveResult backward = dpgen::implicit_solve_backward(
      [&](const VectorXd& v, VectorXd& y) {
        ++transpose_applications;
        apply(v, y);
      },
      [&](const VectorXd& xs, const VectorXd& lambda, VectorXd& g) {
        ++adjoint_calls;
        pr.adjoint_k(xs, lambda, g);
      },
      x, x - target, b_bar, k_bar, options);
  CHECK(backward.summary.converged());
  // One backward solve and one adjoint call: nothing per forward iteration is stored or replayed.
  CHECK(adjoint_calls == 1);
  CHECK(transpose_applications == backward.summary.iterations);

  // x is linear in b: the central difference is exact up to the solve's rounding, so a large
  // step is fine. x(k) is smooth: step 1e-4 leaves an O(1e-8) truncation error.
  const VectorXd fd_b = central_differences(
      [&](const VectorXd& bb) { return loss(solve(pr.k, bb), target); }, b, 1e-3);
  const VectorXd fd_k = central_differences(
      [&](const VectorXd& kk) { return loss(solve(kk, b), target); }, pr.k, 1e-4);
  CHECK(relative_error(b_bar, fd_b) < 1e-6);
  CHECK(relative_error(k_bar, fd_k) < 1e-6);
  // b_bar is lambda itself (b_bar started empty, i.e. zero).
  CHECK(b_bar == backward.solution);
}

TEST_CASE("implicit gradients agree with differentiating through the unrolled CG iterations") {
  const Problem1d pr;
  const VectorXd b = random_vector(pr.n, 41), target = random_vector(pr.n, 42, -0.01, 0.01);
  const double tolerance = 1e-10;
  dpgen::CgOptions options;
  options.relative_tolerance = tolerance;
  const auto apply = [&](const VectorXd& v, VectorXd& y) { pr.apply(pr.k, v, y); };
  const dpgen::LinearSolveResult forward = dpgen::solve_forward(apply, b, options);
  const VectorXd& x = forward.solution;

  // The reference runs the same iterations and keeps every iterate (O(n * iterations)).
  CgTape tape;
  const VectorXd x_unrolled = unrolled_cg(apply, b, forward.summary.iterations, tape);
  CHECK((x_unrolled - x).norm() <= 1e-14 * x.norm()); // the same algorithm, step for step
  VectorXd b_bar_ref = VectorXd::Zero(pr.n), k_bar_ref = VectorXd::Zero(pr.n + 1);
  unrolled_cg_backward(
      apply,
      [&](const VectorXd& p, const VectorXd& q_bar, VectorXd& g) { pr.adjoint_k(p, q_bar, g); },
      tape, b, x_unrolled - target, b_bar_ref, k_bar_ref);

  VectorXd b_bar = VectorXd::Zero(pr.n), k_bar = VectorXd::Zero(pr.n + 1);
  dpgen::implicit_solve_backward(
      apply, [&](const VectorXd& xs, const VectorXd& l, VectorXd& g) { pr.adjoint_k(xs, l, g); }, x,
      x - target, b_bar, k_bar, options);
  // Both are the exact derivative up to the solve error, which is at most cond(A) * tolerance
  // in relative terms; cond(A) is about 4 / (pi h)^2 * max k / min k < 2e3 here.
  const double bound = 2e3 * tolerance;
  CHECK(relative_error(b_bar, b_bar_ref) < bound);
  CHECK(relative_error(k_bar, k_bar_ref) < bound);
}

TEST_CASE("warm-starting the backward solve with a previous lambda") {
  const Problem1d pr;
  const auto apply = [&](const VectorXd& v, VectorXd& y) { pr.apply(pr.k, v, y); };
  const VectorXd x_bar = random_vector(pr.n, 51);
  const dpgen::LinearSolveResult cold = dpgen::solve_backward(apply, x_bar);
  const VectorXd x_bar_near = x_bar + 1e-6 * random_vector(pr.n, 52);
  const dpgen::LinearSolveResult warm =
      dpgen::solve_backward(apply, x_bar_near, {}, &cold.solution);
  const dpgen::LinearSolveResult cold_near = dpgen::solve_backward(apply, x_bar_near);
  CHECK(warm.summary.converged());
  CHECK(warm.summary.iterations < cold_near.summary.iterations);
  CHECK(relative_error(warm.solution, cold_near.solution) < 1e-6);
}

TEST_CASE("implicit solves: initial_guess is the one way to start elsewhere than zero") {
  const Problem1d pr;
  const auto apply = [&](const VectorXd& v, VectorXd& y) { pr.apply(pr.k, v, y); };
  const VectorXd b = random_vector(pr.n, 53);
  dpgen::CgOptions options;
  options.relative_tolerance = 1e-12;
  const dpgen::LinearSolveResult cold = dpgen::solve_forward(apply, b, options);
  REQUIRE(cold.summary.iterations > 0);
  // Started at the solution: converged at once, forward and backward (A symmetric).
  const dpgen::LinearSolveResult at_solution =
      dpgen::solve_forward(apply, b, options, &cold.solution);
  CHECK(at_solution.summary.iterations == 0);
  CHECK(at_solution.solution == cold.solution);
  const dpgen::LinearSolveResult backward_at_solution =
      dpgen::solve_backward(apply, b, options, &cold.solution);
  CHECK(backward_at_solution.summary.iterations == 0);
  VectorXd b_bar, k_bar = VectorXd::Zero(33);
  const auto adjoint = [&](const VectorXd& x, const VectorXd& l, VectorXd& g) {
    pr.adjoint_k(x, l, g);
  };
  CHECK(dpgen::implicit_solve_backward(apply, adjoint, cold.solution, b, b_bar, k_bar, options,
                                       &cold.solution)
            .summary.iterations == 0);
  CHECK(dpgen::solve_forward_normal(apply, apply, b, options, &cold.solution)
            .summary.initial_residual_norm < 1e-6 * b.norm());
}

TEST_CASE("implicit solves with a CgWorkspace: same bits, no reallocation across solves") {
  const Problem1d pr;
  const auto apply = [&](const VectorXd& v, VectorXd& y) { pr.apply(pr.k, v, y); };
  const auto adjoint = [&](const VectorXd& x, const VectorXd& l, VectorXd& g) {
    pr.adjoint_k(x, l, g);
  };
  dpgen::CgOptions plain;
  plain.relative_tolerance = 1e-12;
  dpgen::CgWorkspace workspace;
  dpgen::CgOptions reused = plain;
  reused.workspace = &workspace;
  const double* buffers[4] = {};
  for (int round = 0; round < 3; ++round) {
    CAPTURE(round);
    const VectorXd b = random_vector(pr.n, 54 + round), x_bar = random_vector(pr.n, 64 + round);
    const dpgen::LinearSolveResult f_plain = dpgen::solve_forward(apply, b, plain);
    const dpgen::LinearSolveResult f_reused = dpgen::solve_forward(apply, b, reused);
    CHECK(f_plain.solution == f_reused.solution);
    VectorXd b_bar_plain, k_bar_plain = VectorXd::Zero(33);
    VectorXd b_bar_reused, k_bar_reused = VectorXd::Zero(33);
    const dpgen::LinearSolveResult l_plain = dpgen::implicit_solve_backward(
        apply, adjoint, f_plain.solution, x_bar, b_bar_plain, k_bar_plain, plain);
    const dpgen::LinearSolveResult l_reused = dpgen::implicit_solve_backward(
        apply, adjoint, f_reused.solution, x_bar, b_bar_reused, k_bar_reused, reused);
    CHECK(l_plain.solution == l_reused.solution);
    CHECK(k_bar_plain == k_bar_reused);
    CHECK(l_plain.summary.iterations == l_reused.summary.iterations);
    const double* now[4] = {workspace.r.data(), workspace.z.data(), workspace.p.data(),
                            workspace.q.data()};
    for (int i = 0; i < 4; ++i) {
      CHECK(now[i] != nullptr);
      if (round > 0)
        CHECK(now[i] == buffers[i]);
      buffers[i] = now[i];
    }
  }
}

TEST_CASE("periodic Poisson: gradients with null-space mean removal") {
  const int nx = 8, ny = 6, n = nx * ny;
  const double h = 1.0 / nx;
  const VectorXd k = random_vector(n, 61, 0.5, 2.0);
  const VectorXd b = random_vector(n, 62), target = random_vector(n, 63, -0.01, 0.01);
  dpgen::CgOptions options;
  options.remove_null_space_mean = true;
  options.relative_tolerance = 1e-13;
  const auto op = [&](const VectorXd& kk) {
    return [&, kk](const VectorXd& v, VectorXd& y) {
      neg_div_k_grad_periodic2d(v.data(), kk.data(), y.data(), nx, ny, h);
    };
  };
  const auto solve = [&](const VectorXd& kk, const VectorXd& rhs) {
    return dpgen::solve_forward(op(kk), rhs, options).solution;
  };
  const VectorXd x = solve(k, b);
  CHECK(std::abs(x.mean()) < 1e-14);

  VectorXd b_bar, k_bar = VectorXd::Zero(n);
  const dpgen::LinearSolveResult backward = dpgen::implicit_solve_backward(
      op(k),
      [&](const VectorXd& xs, const VectorXd& lambda, VectorXd& g) {
        VectorXd x_adj = VectorXd::Zero(n);
        neg_div_k_grad_periodic2d_adjoint(xs.data(), x_adj.data(), k.data(), g.data(),
                                          lambda.data(), nx, ny, h);
      },
      x, x - target, b_bar, k_bar, options);
  CHECK(backward.summary.converged());
  CHECK(std::abs(backward.solution.mean()) < 1e-14);

  const VectorXd fd_b =
      central_differences([&](const VectorXd& bb) { return loss(solve(k, bb), target); }, b, 1e-3);
  const VectorXd fd_k =
      central_differences([&](const VectorXd& kk) { return loss(solve(kk, b), target); }, k, 1e-4);
  CHECK(relative_error(b_bar, fd_b) < 1e-6);
  CHECK(relative_error(k_bar, fd_k) < 1e-6);

  // Without mean removal the singular system has no solution for this b.
  dpgen::CgOptions plain = options;
  plain.remove_null_space_mean = false;
  plain.max_iterations = 300;
  CHECK_THROWS_AS(dpgen::solve_forward(op(k), b, plain), dpgen::SolveError);
}

TEST_CASE("non-symmetric operator: CG on the normal equations, gradients vs differences") {
  const Problem1d pr;
  const Advection adv{pr.n, 3.0, pr.h, 5.0};
  const auto a = [&](const VectorXd& kk) {
    return [&, kk](const VectorXd& v, VectorXd& y) {
      pr.apply(kk, v, y);
      adv.apply(v, y);
    };
  };
  const auto a_transpose = [&](const VectorXd& kk) {
    return [&, kk](const VectorXd& v, VectorXd& y) {
      pr.apply(kk, v, y); // the diffusion part is symmetric
      adv.apply_transpose(v, y);
    };
  };
  const VectorXd b = random_vector(pr.n, 71), target = random_vector(pr.n, 72, -0.01, 0.01);
  dpgen::CgOptions options;
  options.relative_tolerance = 1e-14;
  options.max_iterations = 5000;
  const auto solve = [&](const VectorXd& kk, const VectorXd& rhs) {
    return dpgen::solve_forward_normal(a(kk), a_transpose(kk), rhs, options).solution;
  };
  const VectorXd x = solve(pr.k, b);
  VectorXd ax = VectorXd::Zero(pr.n);
  a(pr.k)(x, ax);
  CHECK((ax - b).norm() < 1e-8 * b.norm());

  VectorXd b_bar, k_bar = VectorXd::Zero(pr.n + 1);
  dpgen::implicit_solve_backward_normal(
      a(pr.k), a_transpose(pr.k),
      [&](const VectorXd& xs, const VectorXd& lambda, VectorXd& g) { pr.adjoint_k(xs, lambda, g); },
      x, x - target, b_bar, k_bar, options);
  // lambda solves A^T lambda = x_bar.
  VectorXd atl = VectorXd::Zero(pr.n);
  a_transpose(pr.k)(b_bar, atl);
  CHECK((atl - (x - target)).norm() < 1e-8 * (x - target).norm());

  const VectorXd fd_b = central_differences(
      [&](const VectorXd& bb) { return loss(solve(pr.k, bb), target); }, b, 1e-3);
  const VectorXd fd_k = central_differences(
      [&](const VectorXd& kk) { return loss(solve(kk, b), target); }, pr.k, 1e-4);
  CHECK(relative_error(b_bar, fd_b) < 1e-6);
  CHECK(relative_error(k_bar, fd_k) < 1e-6);
}

TEST_CASE("implicit solve errors say which pass failed") {
  const Problem1d pr;
  const auto apply = [&](const VectorXd& v, VectorXd& y) { pr.apply(pr.k, v, y); };
  const auto adjoint = [&](const VectorXd& xs, const VectorXd& l, VectorXd& g) {
    pr.adjoint_k(xs, l, g);
  };
  const VectorXd b = random_vector(pr.n, 81);
  const VectorXd x = dpgen::solve_forward(apply, b).solution;
  VectorXd b_bar, k_bar = VectorXd::Zero(pr.n + 1);

  dpgen::CgOptions few;
  few.max_iterations = 3;
  try {
    dpgen::implicit_solve_backward(apply, adjoint, x, b, b_bar, k_bar, few);
    FAIL("expected a SolveError");
  } catch (const dpgen::SolveError& e) {
    const std::string what = e.what();
    CHECK(what.rfind("cg backward (A^T lambda = x_bar): did not converge after 3 iterations, "
                     "residual ",
                     0) == 0);
    CHECK(e.summary().iterations == 3);
  }
  CHECK_THROWS_WITH_AS(dpgen::solve_forward(apply, b, few),
                       doctest::Contains("cg forward (A x = b): did not converge after 3"),
                       dpgen::SolveError);

  // The Laplacian's sign is easy to get wrong in the transposed operator.
  const auto negated = [&](const VectorXd& v, VectorXd& y) {
    apply(v, y);
    y = -y;
  };
  CHECK_THROWS_WITH_AS(
      dpgen::implicit_solve_backward(negated, adjoint, x, b, b_bar, k_bar),
      doctest::Contains(
          "backward (A^T lambda = x_bar): operator is not symmetric positive definite"),
      dpgen::SolveError);

  VectorXd bad = b;
  bad[2] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(dpgen::implicit_solve_backward(apply, adjoint, x, bad, b_bar, k_bar),
                       "cg backward (A^T lambda = x_bar): x_bar contains nan at index 2",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(
      dpgen::implicit_solve_backward(apply, adjoint, x, VectorXd::Ones(5), b_bar, k_bar),
      "cg backward (A^T lambda = x_bar): x_bar has size 5, expected 32", std::invalid_argument);
  const auto short_adjoint = [](const VectorXd&, const VectorXd&, VectorXd& g) {
    g = VectorXd::Zero(3);
  };
  CHECK_THROWS_WITH_AS(
      dpgen::implicit_solve_backward(apply, short_adjoint, x, b, b_bar, k_bar),
      "implicit solve gradients: operator adjoint returned a theta gradient of size 3, expected 33",
      std::invalid_argument);
  VectorXd wrong_b_bar = VectorXd::Zero(7);
  CHECK_THROWS_WITH_AS(dpgen::implicit_solve_backward(apply, adjoint, x, b, wrong_b_bar, k_bar),
                       "implicit solve gradients: b_bar has size 7, expected 32",
                       std::invalid_argument);
}
