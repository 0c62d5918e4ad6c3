// Matrix-free preconditioned conjugate gradient for symmetric positive definite operators given
// as callables y = A(x) (typically a generated stencil kernel), in the shape of Ceres's solver.
#pragma once

#include "dpgen/error.hpp"
#include "dpgen/parallel.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

namespace dpgen {

/// A linear map on vectors, called as `op(x, y)` to compute y = A x. `y` arrives sized like `x`
/// and zero-filled, so a kernel may either assign or accumulate into it.
using VectorOperator = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;

/// Why conjugate_gradient stopped.
enum class CgTermination {
  converged,          ///< ||r|| <= tolerance
  max_iterations,     ///< the iteration limit was reached first
  negative_curvature, ///< p^T A p <= 0 (or r^T M^-1 r <= 0): A or M is not SPD
  nan,                ///< a NaN or Inf appeared in the iteration
};

/// The enumerator's name, for messages and logs.
inline const char* to_string(CgTermination termination) {
  switch (termination) {
  case CgTermination::converged:
    return "converged";
  case CgTermination::max_iterations:
    return "max_iterations";
  case CgTermination::negative_curvature:
    return "negative_curvature";
  case CgTermination::nan:
    return "nan";
  }
  return "unknown";
}

/// The work vectors of conjugate_gradient: residual r, preconditioned residual z, search
/// direction p and q = A p. Pass one through CgOptions::workspace to reuse them across solves
/// (a time loop's pressure solves, an implicit backward pass per training iteration): they are
/// resized on first use and keep their storage afterwards. Their contents between solves are
/// meaningless.
struct CgWorkspace {
  Eigen::VectorXd r, z, p, q;
};

/// Settings of one conjugate-gradient solve. The defaults solve to 1e-10 relative residual and
/// throw when that is not reached.
struct CgOptions {
  /// Converged when ||b - A x|| <= max(relative_tolerance * ||b||, absolute_tolerance), with b
  /// and the residual taken after null-space mean removal when that is on.
  double relative_tolerance = 1e-10;
  /// Absolute floor of the tolerance above (useful when b may be zero).
  double absolute_tolerance = 0.0;
  /// Largest number of operator applications in the iteration (must be >= 0).
  int max_iterations = 1000;
  /// Jacobi preconditioner M = diag(jacobi_diagonal): the diagonal of A, every entry positive.
  /// Empty means no Jacobi preconditioner.
  Eigen::VectorXd jacobi_diagonal;
  /// A general SPD preconditioner, called as `preconditioner(r, z)` to compute z = M^-1 r, such
  /// as Multigrid::preconditioner() (dpgen/solvers/multigrid.hpp). It must be a fixed linear map
  /// (not an inner iteration to a tolerance). Empty means none. At most one of jacobi_diagonal
  /// and preconditioner may be set.
  VectorOperator preconditioner;
  /// For operators whose null space is the constant vector (periodic or all-Neumann Poisson):
  /// the mean of the right-hand side is removed (the solvable part P b, P v = v - mean(v)),
  /// the residual and the preconditioned residual are kept mean-free, and the returned x is
  /// the mean-free solution. Assumes A 1 = 0 and A^T 1 = 0.
  bool remove_null_space_mean = false;
  /// Throw SolveError when the solve did not converge; otherwise only the summary reports it.
  bool throw_on_failure = true;
  /// Prefix of every message, so an error says which solve failed ("cg", "implicit solve
  /// backward (A^T lambda = x_bar)").
  std::string name = "cg";
  /// Scratch vectors for the iteration (see CgWorkspace), owned by the caller and reused by
  /// every solve given these options, so repeated solves of one size allocate nothing. Null:
  /// each solve allocates its own. Results are bit-identical either way. One workspace must
  /// not serve two solves at the same time.
  CgWorkspace* workspace = nullptr;
};

/// What a conjugate-gradient solve did. Residuals are Euclidean norms of r = b - A x as updated
/// by the recurrence (the same quantity Eigen's ConjugateGradient reports).
struct CgSummary {
  int iterations = 0;                ///< operator applications inside the iteration
  double initial_residual_norm = 0.; ///< ||b - A x0||
  double final_residual_norm = 0.;   ///< ||r|| when the iteration stopped
  double tolerance = 0.;             ///< the residual norm the solve had to reach
  CgTermination termination = CgTermination::max_iterations;
  std::string message; ///< one line saying what happened, with numbers

  /// True when the residual reached the tolerance.
  bool converged() const { return termination == CgTermination::converged; }
};

/// Thrown when a solve fails (no convergence, non-SPD operator, NaN); carries the summary.
class SolveError : public std::runtime_error {
public:
  explicit SolveError(CgSummary summary)
      : std::runtime_error(summary.message), summary_(std::move(summary)) {}
  /// The summary of the failed solve (iterations, residuals, termination reason).
  const CgSummary& summary() const { return summary_; }

private:
  CgSummary summary_;
};

/// Wraps a raw-pointer kernel `kernel(const double* x, double* y)` acting on fields of `n`
/// values as a VectorOperator that refuses vectors of any other size (instead of reading or
/// writing out of bounds).
template <typename Kernel>
VectorOperator kernel_operator(Eigen::Index n, Kernel kernel, std::string name = "operator") {
  return [n, kernel = std::move(kernel), name = std::move(name)](const Eigen::VectorXd& x,
                                                                 Eigen::VectorXd& y) {
    if (x.size() != n)
      throw std::invalid_argument(detail::message(name, ": field of size ", x.size(),
                                                  " passed to an operator on ", n, " cells"));
    y.resize(n);
    kernel(x.data(), y.data());
  };
}

namespace detail {

// P v = v - mean(v) 1: the orthogonal projection onto the complement of the constant vector.
inline void remove_mean(Eigen::VectorXd& v) {
  const Eigen::Index n = v.size();
  if (n == 0)
    return;
  double* p = v.data();
  const double mean =
      parallel_chunks(n,
                      [&](Eigen::Index lo, Eigen::Index hi) {
                        return Eigen::Map<const Eigen::VectorXd>(p + lo, hi - lo).sum();
                      }) /
      static_cast<double>(n);
  parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
    for (Eigen::Index i = lo; i < hi; ++i)
      p[i] -= mean;
    return 0.0;
  });
}

// v = 0, on every thread for long vectors (the operator and preconditioner contract: their
// output arrives zero-filled).
inline void set_zero(Eigen::VectorXd& v, Eigen::Index n) {
  v.resize(n);
  double* p = v.data();
  parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
    std::fill(p + lo, p + hi, 0.0);
    return 0.0;
  });
}

inline void check_cg_options(const CgOptions& options, Eigen::Index n) {
  const std::string& where = options.name;
  if (!(options.relative_tolerance >= 0.0) || !(options.absolute_tolerance >= 0.0))
    throw std::invalid_argument(message(where, ": tolerances must be >= 0 (relative ",
                                        options.relative_tolerance, ", absolute ",
                                        options.absolute_tolerance, ")"));
  if (options.max_iterations < 0)
    throw std::invalid_argument(
        message(where, ": max_iterations must be >= 0 (got ", options.max_iterations, ")"));
  if (options.jacobi_diagonal.size() > 0 && options.preconditioner)
    throw std::invalid_argument(
        message(where, ": set either jacobi_diagonal or preconditioner, not both"));
  if (options.jacobi_diagonal.size() > 0) {
    require_size(options.jacobi_diagonal.size(), n, where, "jacobi_diagonal");
    for (Eigen::Index i = 0; i < n; ++i)
      if (!(options.jacobi_diagonal[i] > 0.0) || !std::isfinite(options.jacobi_diagonal[i]))
        throw std::invalid_argument(message(where, ": jacobi_diagonal[", i,
                                            "] = ", options.jacobi_diagonal[i],
                                            " is not a positive finite number"));
  }
}

} // namespace detail

/// Solves A x = b for a symmetric positive definite A given as a callable `apply(x, y)`
/// computing y = A x (see VectorOperator), with optional Jacobi or general preconditioning.
///
/// Initial guess (the one way, for every solve of the runtime: conjugate_gradient,
/// solve_forward, solve_backward, implicit_solve_backward, solve_forward_normal and
/// petsc::LinearSolver::solve / solve_transpose / petsc::implicit_solve_backward): the optional
/// last argument `initial_guess`. Null (the default): the iteration starts from zero and the
/// incoming contents of `x` are ignored. Otherwise it starts from *initial_guess, which may be
/// `&x` itself (a warm start from the previous solution kept in x). A guess that already
/// solves the system to the tolerance returns after 0 iterations.
///
/// `x` holds the last iterate on return. Throws std::invalid_argument for bad input (sizes, NaN
/// in b or the guess, options) and SolveError when the solve fails and options.throw_on_failure
/// is set.
template <typename Apply>
CgSummary conjugate_gradient(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                             const CgOptions& options = {},
                             const Eigen::VectorXd* initial_guess = nullptr) {
  using Eigen::VectorXd;
  const std::string& where = options.name;
  const Eigen::Index n = b.size();
  detail::check_cg_options(options, n);
  detail::require_finite(b, where, "right-hand side b");
  if (initial_guess != nullptr) {
    detail::require_size(initial_guess->size(), n, where, "initial guess");
    detail::require_finite(*initial_guess, where, "initial guess");
    if (initial_guess != &x)
      x = *initial_guess;
  } else {
    x.setZero(n);
  }
  const bool project = options.remove_null_space_mean;
  CgWorkspace local;
  CgWorkspace& work = options.workspace != nullptr ? *options.workspace : local;
  VectorXd& r = work.r; // r_k = b - A x_k
  VectorXd& z = work.z; // z_k = M^-1 r_k
  VectorXd& p = work.p; // p_k, the search direction
  VectorXd& q = work.q; // q_k = A p_k
  q.resize(n);
  z.resize(n);
  p.resize(n);

  // q = A v, checked: the operator must return a vector of the input's size.
  auto apply_checked = [&](const VectorXd& v) {
    detail::set_zero(q, n);
    apply(v, q);
    if (q.size() != n)
      throw std::invalid_argument(detail::message(where, ": operator returned a vector of size ",
                                                  q.size(), " for an input of size ", n));
  };
  // z = M^-1 r (then P z when projecting, so the search directions stay mean-free).
  auto precondition = [&](const VectorXd& r) {
    if (options.jacobi_diagonal.size() > 0) {
      const double* pr = r.data();
      const double* d = options.jacobi_diagonal.data();
      double* pz = z.data();
      parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
        for (Eigen::Index i = lo; i < hi; ++i)
          pz[i] = pr[i] / d[i];
        return 0.0;
      });
    } else if (options.preconditioner) {
      detail::set_zero(z, n);
      options.preconditioner(r, z);
      if (z.size() != n)
        throw std::invalid_argument(detail::message(
            where, ": preconditioner returned a vector of size ", z.size(), " for size ", n));
    } else {
      z = r;
    }
    if (project)
      detail::remove_mean(z);
  };

  CgSummary summary;
  // r = P b: the solvable part of the right-hand side.
  r = b;
  if (project)
    detail::remove_mean(r);
  summary.tolerance = std::max(options.relative_tolerance * r.norm(), options.absolute_tolerance);
  if (initial_guess != nullptr) {
    if (project)
      detail::remove_mean(x); // x0 <- P x0
    apply_checked(x);
    r -= q; // r0 = b - A x0
    if (project)
      detail::remove_mean(r);
  }
  summary.initial_residual_norm = r.norm();

  precondition(r);
  p = z;                                         // p0 = z0 = M^-1 r0
  double rz = parallel_dot(r, z);                // rho0 = r0^T z0
  double r_norm = std::sqrt(parallel_dot(r, r)); // ||r_k||
  int k = 0;
  double curvature = 0.0;          // the non-positive value behind negative_curvature
  const char* curvature_what = ""; // which quadratic form it was
  int curvature_iteration = 0;     // the iteration that met it
  for (;;) {
    if (!std::isfinite(r_norm) || !std::isfinite(rz)) {
      summary.termination = CgTermination::nan;
      break;
    }
    if (r_norm <= summary.tolerance) {
      summary.termination = CgTermination::converged;
      break;
    }
    if (!(rz > 0.0)) { // r^T M^-1 r <= 0 with r != 0: the preconditioner is not SPD
      summary.termination = CgTermination::negative_curvature;
      curvature = rz;
      curvature_what = "preconditioner is not positive definite: r^T M^-1 r = ";
      curvature_iteration = k + 1;
      break;
    }
    if (k == options.max_iterations) {
      summary.termination = CgTermination::max_iterations;
      break;
    }
    apply_checked(p);                     // q_k = A p_k
    const double pq = parallel_dot(p, q); // p_k^T A p_k
    ++k;
    if (!std::isfinite(pq)) {
      summary.termination = CgTermination::nan;
      break;
    }
    if (pq <= 0.0) { // a direction of non-positive curvature: A is not SPD
      summary.termination = CgTermination::negative_curvature;
      curvature = pq;
      curvature_what = "operator is not symmetric positive definite: p^T A p = ";
      curvature_iteration = k;
      break;
    }
    const double alpha = rz / pq; // alpha_k = rho_k / (p_k^T A p_k)
    // x_{k+1} = x_k + alpha_k p_k and r_{k+1} = r_k - alpha_k A p_k, in one pass that also
    // sums r_{k+1} (for its mean) or its squares (for its norm).
    {
      double* px = x.data();
      double* pr = r.data();
      const double* pp = p.data();
      const double* pq_ = q.data();
      const double sum = parallel_blocks(n, [&](Eigen::Index lo, Eigen::Index hi) {
        for (Eigen::Index i = lo; i < hi; ++i) {
          px[i] += alpha * pp[i];
          pr[i] -= alpha * pq_[i];
        }
        const Eigen::Map<const VectorXd> block(pr + lo, hi - lo);
        return project ? block.sum() : block.squaredNorm();
      });
      if (project) {
        // r_{k+1} <- P r_{k+1}: rounding must not leak into the null space
        const double mean = sum / static_cast<double>(n);
        r_norm = std::sqrt(parallel_blocks(n, [&](Eigen::Index lo, Eigen::Index hi) {
          for (Eigen::Index i = lo; i < hi; ++i)
            pr[i] -= mean;
          return Eigen::Map<const VectorXd>(pr + lo, hi - lo).squaredNorm();
        }));
      } else {
        r_norm = std::sqrt(sum);
      }
    }
    precondition(r);                           // z_{k+1} = M^-1 r_{k+1}
    const double rz_next = parallel_dot(r, z); // rho_{k+1} = r_{k+1}^T z_{k+1}
    const double beta = rz_next / rz;          // beta_k = rho_{k+1} / rho_k
    rz = rz_next;
    {
      double* pp = p.data();
      const double* pz = z.data();
      parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
        for (Eigen::Index i = lo; i < hi; ++i)
          pp[i] = pz[i] + beta * pp[i]; // p_{k+1} = z_{k+1} + beta_k p_k
        return 0.0;
      });
    }
  }
  if (project)
    detail::remove_mean(x); // the mean-free representative of the solution set

  summary.iterations = k;
  summary.final_residual_norm = r_norm;
  switch (summary.termination) {
  case CgTermination::converged:
    summary.message = detail::message(where, ": converged in ", k, " iterations, residual ", r_norm,
                                      " <= tolerance ", summary.tolerance);
    break;
  case CgTermination::max_iterations:
    summary.message =
        detail::message(where, ": did not converge after ", k, " iterations, residual ", r_norm,
                        " > tolerance ", summary.tolerance);
    break;
  case CgTermination::negative_curvature:
    summary.message =
        detail::message(where, ": ", curvature_what, curvature, " <= 0 at iteration ",
                        curvature_iteration, " (residual ", r_norm,
                        "); a negative definite operator such as a Laplacian must be negated");
    break;
  case CgTermination::nan:
    summary.message = detail::message(where, ": NaN or Inf appeared at iteration ", k,
                                      " (operator or preconditioner output is not finite)");
    break;
  }
  if (!summary.converged() && options.throw_on_failure)
    throw SolveError(summary);
  return summary;
}

} // namespace dpgen
