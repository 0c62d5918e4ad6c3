// The differentiable distributed solve x = A(theta)^-1 b: forward by a PETSc Krylov solve,
// backward by the implicit-function rule (one more solve with A^T), as dpgen/implicit_solve.hpp
// does on one process.
#pragma once

#include "dpgen/mpi/decomposition.hpp"
#include "dpgen/mpi/halo.hpp"
#include "dpgen/petsc/linear_solver.hpp"

#include <Eigen/Core>

#include <stdexcept>
#include <utility>

namespace dpgen::petsc {

// The maths (seed text, "Implicit gradient calculations"), on every rank's block at once.
// With A(theta) x = b and a loss L(x):
//   b_bar = A^-T x_bar =: lambda,   theta_bar = -(d(A(theta) x)/dtheta)^T lambda.
// The second term is the generated adjoint of the operator's halo kernel with respect to theta,
// seeded with lambda on the block's own cells and evaluated at x with exchanged halos. The
// kernel reads theta in the halos too, so its theta adjoint lands partly in the halos: the
// reverse halo exchange adds those parts into the owners' cells before theta_bar takes its
// interior. Nothing of the forward iteration is kept.

/// Adds the implicit-rule gradients for a known lambda = A^-T x_bar:
///   b_bar += lambda,  theta_bar -= (d(A(theta) x)/dtheta)^T lambda.
/// x, lambda, b_bar and theta_bar are interior vectors of `dec` (theta is a cell field on the
/// same decomposition; an empty b_bar is first set to zeros). `operator_adjoint(x, lambda, g)`
/// receives padded arrays: x with exchanged halos, lambda with zero halos, and g zero-filled; it
/// must ADD the kernel's theta adjoint seeded with lambda into g (halos included), e.g.
///   kernel_adjoint(x.data(), scratch, theta.data(), g.data(), lambda.data(), ...).
template <typename OperatorAdjoint>
void accumulate_implicit_gradients(const mpi::Decomposition& dec,
                                   OperatorAdjoint&& operator_adjoint, const Eigen::VectorXd& x,
                                   const Eigen::VectorXd& lambda, Eigen::VectorXd& b_bar,
                                   Eigen::VectorXd& theta_bar) {
  const char* what = "implicit solve gradients";
  dec.require_size(x.size(), dec.interior_size(), std::string(what) + ": x", "block");
  dec.require_size(lambda.size(), dec.interior_size(), std::string(what) + ": lambda", "block");
  dec.require_size(theta_bar.size(), dec.interior_size(), std::string(what) + ": theta_bar",
                   "block");
  if (b_bar.size() == 0)
    b_bar.setZero(x.size());
  dec.require_size(b_bar.size(), dec.interior_size(), std::string(what) + ": b_bar", "block");
  b_bar += lambda; // b_bar += A^-T x_bar

  Eigen::VectorXd x_padded = dec.pad(x);
  mpi::exchange_halos(dec, x_padded); // the operator reads x's neighbours
  const Eigen::VectorXd lambda_padded = dec.pad(lambda);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(dec.padded_size());
  operator_adjoint(static_cast<const Eigen::VectorXd&>(x_padded), lambda_padded, g);
  dec.require_size(g.size(), dec.padded_size(), std::string(what) + ": theta adjoint",
                   "padded block");
  mpi::exchange_halos_adjoint(dec, g); // theta read in the halos: adjoints back to the owners
  theta_bar -= dec.interior(g);        // theta_bar -= (d(A x)/dtheta)^T lambda
}

/// The whole backward pass of x = A(theta)^-1 b at the forward solution x: solves A^T lambda =
/// x_bar (started from `initial_guess` when given, e.g. `&lambda` for the previous lambda;
/// from zero otherwise), then accumulate_implicit_gradients. Returns the backward solve's
/// summary; `lambda` holds its solution.
template <typename OperatorAdjoint>
SolveSummary implicit_solve_backward(LinearSolver& solver, OperatorAdjoint&& operator_adjoint,
                                     const Eigen::VectorXd& x, const Eigen::VectorXd& x_bar,
                                     Eigen::VectorXd& lambda, Eigen::VectorXd& b_bar,
                                     Eigen::VectorXd& theta_bar,
                                     const Eigen::VectorXd* initial_guess = nullptr) {
  SolveSummary s = solver.solve_transpose(x_bar, lambda, initial_guess);
  accumulate_implicit_gradients(solver.decomposition(),
                                std::forward<OperatorAdjoint>(operator_adjoint), x, lambda, b_bar,
                                theta_bar);
  return s;
}

} // namespace dpgen::petsc
