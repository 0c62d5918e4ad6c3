// The differentiable linear solve x = A(theta)^-1 b: forward by CG, backward by the implicit
// function rule (one more CG solve A^T lambda = x_bar), never by unrolling the iterations.
#pragma once

#include "dpgen/cg.hpp"
#include "dpgen/error.hpp"

#include <Eigen/Core>

#include <stdexcept>
#include <string>
#include <utility>

namespace dpgen {

/// One solve's answer: the solution vector and the summary of the CG run that produced it.
struct LinearSolveResult {
  Eigen::VectorXd solution;
  CgSummary summary;
};

// The maths (seed text, "Implicit gradient calculations"). With A(theta) x = b and a loss L(x):
//   db:     A dx = db                    => b_bar = A^-T x_bar =: lambda
//   dtheta: dA x + A dx = 0              => theta_bar = -(d(A(theta) x)/dtheta)^T lambda
// so the backward pass is one solve with A^T (A itself when A is symmetric) plus one call of
// the operator kernel's adjoint with respect to theta, seeded with lambda and evaluated at the
// forward solution x. Nothing of the forward iteration is kept: memory is O(n), independent of
// the number of CG iterations.
//
// With a constant null space (options.remove_null_space_mean), the forward solve returns the
// mean-free x = A^+ P b, and the same formulas hold with lambda = A^+ P x_bar (the backward
// solve removes the mean of x_bar), provided A(theta) 1 = 0 for every theta.
//
// Preconditioning: forward and backward take the same CgOptions, so a preconditioner set there
// (Jacobi, or a Multigrid V-cycle from dpgen/solvers/multigrid.hpp) serves both solves without a
// second setup. That is right because A^T = A here: M ~ A^-1 is also M ~ A^-T, and the backward
// solve converges as fast as the forward one. For a non-symmetric A, CG does not apply to A itself:
// solve_forward_normal / solve_backward_normal below run CG on A^T A, for which M ~ A^-1 is not
// a preconditioner (M M^T would be, with M^T a V-cycle built on A^T). A Multigrid refuses a
// non-symmetric operator at setup, so it cannot be passed there by mistake.

namespace detail {

inline CgOptions named(const CgOptions& options, const char* suffix) {
  CgOptions named_options = options;
  named_options.name = options.name + suffix;
  return named_options;
}

} // namespace detail

/// Forward solve of A x = b by conjugate_gradient; A must be SPD (or SPD on the complement of
/// the constants with options.remove_null_space_mean). Errors are prefixed
/// "<options.name> forward (A x = b)". `initial_guess`, when given, starts the iteration
/// (otherwise it starts from zero; see conjugate_gradient). A CgWorkspace in the options is
/// reused.
template <typename Apply>
LinearSolveResult solve_forward(Apply&& apply, const Eigen::VectorXd& b,
                                const CgOptions& options = {},
                                const Eigen::VectorXd* initial_guess = nullptr) {
  const CgOptions forward = detail::named(options, " forward (A x = b)");
  LinearSolveResult result;
  result.summary = conjugate_gradient(apply, b, result.solution, forward, initial_guess);
  return result;
}

/// Backward solve A^T lambda = x_bar, where `apply_transpose(v, y)` computes y = A^T v (pass
/// the forward operator for a symmetric A). `initial_guess`, e.g. the previous lambda in a
/// time loop, starts the iteration (otherwise it starts from zero). Errors are prefixed
/// "<options.name> backward (A^T lambda = x_bar)", so a failure says it happened in the
/// backward pass.
template <typename ApplyTranspose>
LinearSolveResult solve_backward(ApplyTranspose&& apply_transpose, const Eigen::VectorXd& x_bar,
                                 const CgOptions& options = {},
                                 const Eigen::VectorXd* initial_guess = nullptr) {
  const CgOptions backward = detail::named(options, " backward (A^T lambda = x_bar)");
  detail::require_finite(x_bar, backward.name, "x_bar");
  LinearSolveResult result;
  result.summary =
      conjugate_gradient(apply_transpose, x_bar, result.solution, backward, initial_guess);
  return result;
}

/// Accumulates the implicit-function-rule gradients for a known lambda = A^-T x_bar:
///   b_bar += lambda,  theta_bar -= (d(A(theta) x)/dtheta)^T lambda.
/// `operator_adjoint(x, lambda, g)` must ADD (d(A(theta) x)/dtheta)^T lambda into g, as a
/// generated kernel adjoint does with its `<theta>_adj` argument when its output adjoint is
/// seeded with lambda; g arrives zero-filled with theta_bar's size, so the result can be
/// subtracted. An empty b_bar is first resized to zeros.
template <typename OperatorAdjoint>
void accumulate_implicit_gradients(OperatorAdjoint&& operator_adjoint, const Eigen::VectorXd& x,
                                   const Eigen::VectorXd& lambda, Eigen::VectorXd& b_bar,
                                   Eigen::VectorXd& theta_bar) {
  const char* where = "implicit solve gradients";
  detail::require_size(lambda.size(), x.size(), where, "lambda");
  if (b_bar.size() == 0)
    b_bar.setZero(x.size());
  detail::require_size(b_bar.size(), x.size(), where, "b_bar");
  b_bar += lambda; // b_bar += A^-T x_bar

  Eigen::VectorXd g = Eigen::VectorXd::Zero(theta_bar.size());
  operator_adjoint(x, lambda, g); // g = (d(A(theta) x)/dtheta)^T lambda
  if (g.size() != theta_bar.size())
    throw std::invalid_argument(
        detail::message(where, ": operator adjoint returned a theta gradient of size ", g.size(),
                        ", expected ", theta_bar.size()));
  theta_bar -= g; // theta_bar -= (d(A x)/dtheta)^T lambda
}

/// The whole backward pass of x = A(theta)^-1 b for a loss gradient x_bar at the forward
/// solution x: solves A^T lambda = x_bar (solve_backward), then accumulate_implicit_gradients.
/// Returns lambda and the backward solve's summary (lambda can be the next call's
/// `initial_guess`).
template <typename ApplyTranspose, typename OperatorAdjoint>
LinearSolveResult implicit_solve_backward(ApplyTranspose&& apply_transpose,
                                          OperatorAdjoint&& operator_adjoint,
                                          const Eigen::VectorXd& x, const Eigen::VectorXd& x_bar,
                                          Eigen::VectorXd& b_bar, Eigen::VectorXd& theta_bar,
                                          const CgOptions& options = {},
                                          const Eigen::VectorXd* initial_guess = nullptr) {
  detail::require_size(x_bar.size(), x.size(), options.name + " backward (A^T lambda = x_bar)",
                       "x_bar");
  LinearSolveResult result = solve_backward(apply_transpose, x_bar, options, initial_guess);
  accumulate_implicit_gradients(operator_adjoint, x, result.solution, b_bar, theta_bar);
  return result;
}

// Non-symmetric A: CG needs an SPD operator, so both directions run CG on the normal equations
// with A^T A (whose condition number is cond(A)^2: use this only for well-conditioned A).
//   forward:  A^T A x = A^T b                      (CGNR)
//   backward: A^T lambda = x_bar, lambda = A mu, A^T A mu = x_bar   (CGNE on A^T)

/// Forward solve of a non-symmetric A x = b through the normal equations A^T A x = A^T b;
/// the tolerances apply to the normal-equation residual A^T (b - A x).
template <typename Apply, typename ApplyTranspose>
LinearSolveResult solve_forward_normal(Apply&& apply, ApplyTranspose&& apply_transpose,
                                       const Eigen::VectorXd& b, const CgOptions& options = {},
                                       const Eigen::VectorXd* initial_guess = nullptr) {
  const CgOptions forward = detail::named(options, " forward (A^T A x = A^T b)");
  detail::require_finite(b, forward.name, "right-hand side b");
  Eigen::VectorXd atb = Eigen::VectorXd::Zero(b.size());
  apply_transpose(b, atb); // A^T b
  detail::require_size(atb.size(), b.size(), forward.name, "A^T b");
  Eigen::VectorXd av(b.size());
  auto normal = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    av.setZero(v.size());
    apply(v, av);           // A v
    apply_transpose(av, y); // A^T (A v)
  };
  LinearSolveResult result;
  result.summary = conjugate_gradient(normal, atb, result.solution, forward, initial_guess);
  return result;
}

/// Backward solve A^T lambda = x_bar for a non-symmetric A: lambda = A mu with A^T A mu =
/// x_bar, started from zero (a guess for lambda is no guess for mu: no initial_guess here).
/// Errors are prefixed "<options.name> backward (A^T A mu = x_bar)".
template <typename Apply, typename ApplyTranspose>
LinearSolveResult solve_backward_normal(Apply&& apply, ApplyTranspose&& apply_transpose,
                                        const Eigen::VectorXd& x_bar,
                                        const CgOptions& options = {}) {
  const CgOptions backward = detail::named(options, " backward (A^T A mu = x_bar)");
  detail::require_finite(x_bar, backward.name, "x_bar");
  Eigen::VectorXd av(x_bar.size());
  auto normal = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    av.setZero(v.size());
    apply(v, av);           // A v
    apply_transpose(av, y); // A^T (A v)
  };
  Eigen::VectorXd mu;
  LinearSolveResult result;
  result.summary = conjugate_gradient(normal, x_bar, mu, backward);
  result.solution.setZero(x_bar.size());
  apply(mu, result.solution); // lambda = A mu
  detail::require_size(result.solution.size(), x_bar.size(), backward.name, "A mu");
  return result;
}

/// implicit_solve_backward for a non-symmetric A solved with solve_forward_normal.
template <typename Apply, typename ApplyTranspose, typename OperatorAdjoint>
LinearSolveResult
implicit_solve_backward_normal(Apply&& apply, ApplyTranspose&& apply_transpose,
                               OperatorAdjoint&& operator_adjoint, const Eigen::VectorXd& x,
                               const Eigen::VectorXd& x_bar, Eigen::VectorXd& b_bar,
                               Eigen::VectorXd& theta_bar, const CgOptions& options = {}) {
  detail::require_size(x_bar.size(), x.size(), options.name + " backward (A^T A mu = x_bar)",
                       "x_bar");
  LinearSolveResult result = solve_backward_normal(apply, apply_transpose, x_bar, options);
  accumulate_implicit_gradients(operator_adjoint, x, result.solution, b_bar, theta_bar);
  return result;
}

} // namespace dpgen
