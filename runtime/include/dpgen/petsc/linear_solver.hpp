// Distributed linear solves with PETSc for operators given as kernels on padded blocks: a
// MatShell whose mult is "halo exchange, then the kernel", KSP (CG for symmetric operators)
// preconditioned from an assembled copy of the operator obtained by probing it.
#pragma once

#include "dpgen/error.hpp"
#include "dpgen/mpi/decomposition.hpp"
#include "dpgen/mpi/halo.hpp"

#include <Eigen/Core>
#include <mpi.h>
#include <petscksp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dpgen::petsc {

/// Initializes PETSc for the lifetime of the object (after MPI_Init, before any solver) and
/// finalizes it at the end; MPI itself stays initialized. PETSc reads its options from the
/// PETSC_OPTIONS environment variable (e.g. PETSC_OPTIONS="-ksp_monitor"). Every LinearSolver
/// must be destroyed before the Session.
class Session {
public:
  Session() {
    PetscBool initialized = PETSC_FALSE;
    PetscInitialized(&initialized);
    if (!initialized) {
      if (PetscInitializeNoArguments() != 0)
        throw std::runtime_error("petsc: PetscInitializeNoArguments failed");
      owner_ = true;
    }
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  ~Session() {
    if (owner_)
      PetscFinalize();
  }

private:
  bool owner_ = false;
};

/// Whether this PETSc was built with hypre (BoomerAMG); asked of PETSc at run time.
inline bool has_hypre() {
  PetscBool has = PETSC_FALSE;
  PetscHasExternalPackage("hypre", &has);
  return has == PETSC_TRUE;
}

/// The preconditioner of the Krylov solve.
enum class Preconditioner {
  automatic, ///< symmetric: BoomerAMG when PETSc has hypre, else GAMG; non-symmetric: Jacobi
  boomeramg, ///< hypre's algebraic multigrid (PCHYPRE, boomeramg)
  gamg,      ///< PETSc's own algebraic multigrid (PCGAMG)
  jacobi,    ///< the diagonal of the operator (PCJACOBI)
  none,      ///< no preconditioner (PCNONE); no assembled copy is built
};

/// "automatic", "boomeramg", "gamg", "jacobi" or "none" -> the enumerator (for command lines).
inline Preconditioner parse_preconditioner(const std::string& name) {
  if (name == "automatic" || name == "auto")
    return Preconditioner::automatic;
  if (name == "boomeramg" || name == "hypre")
    return Preconditioner::boomeramg;
  if (name == "gamg")
    return Preconditioner::gamg;
  if (name == "jacobi")
    return Preconditioner::jacobi;
  if (name == "none")
    return Preconditioner::none;
  throw std::invalid_argument("petsc: unknown preconditioner '" + name +
                              "' (automatic, boomeramg, gamg, jacobi or none)");
}

/// Settings of a LinearSolver.
struct SolverOptions {
  /// Prefix of every message ("pressure solve").
  std::string name = "petsc solve";
  /// Converged when ||b - A x|| <= max(relative_tolerance ||b||, absolute_tolerance), with the
  /// unpreconditioned residual (b after null-space removal when that is on), as in dpgen::cg.
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-50;
  int max_iterations = 10000;
  Preconditioner preconditioner = Preconditioner::automatic;
  /// Symmetric operators are solved with CG, and the transposed solve is the same solve.
  /// Non-symmetric ones with GMRES (right-preconditioned), transposed by KSPSolveTranspose,
  /// which needs the operator's transpose (LinearSolver's apply_transpose).
  bool symmetric = true;
  /// For operators whose null space is the constants (periodic or all-Neumann Poisson): the
  /// constant is removed from right-hand sides and solutions (PETSc MatNullSpace), which come
  /// out mean-free, as with dpgen::CgOptions::remove_null_space_mean.
  bool constant_null_space = false;
  /// Cells an output cell of the kernel reaches in each direction (1 for 3-, 5- and 7-point
  /// stencils): sets how the operator is probed for the preconditioner's assembled copy.
  int stencil_radius = 1;
  /// Throw SolveError when a solve does not converge; otherwise only the summary says so.
  bool throw_on_failure = true;
  /// Prefix of this solver's KSP in PETSc's options database (PETSC_OPTIONS="-<prefix>ksp_...").
  std::string options_prefix;
};

/// What one distributed solve did (the same on every rank).
struct SolveSummary {
  int iterations = 0;
  double residual_norm = 0.;  ///< ||b - A x|| when the iteration stopped
  double rhs_norm = 0.;       ///< ||b|| (after null-space removal)
  double tolerance = 0.;      ///< the residual norm the solve had to reach
  int reason = 0;             ///< PETSc's KSPConvergedReason
  std::string reason_name;    ///< its name, e.g. "CONVERGED_RTOL", "DIVERGED_ITS"
  std::string preconditioner; ///< the preconditioner used, e.g. "hypre boomeramg"
  std::string message;        ///< one line saying what happened, with numbers
  bool converged() const { return reason > 0; }
};

/// Thrown when a distributed solve does not converge; carries the summary. Every rank throws it
/// alike (PETSc's convergence test is global).
class SolveError : public std::runtime_error {
public:
  explicit SolveError(SolveSummary summary)
      : std::runtime_error(summary.message), summary_(std::move(summary)) {}
  const SolveSummary& summary() const { return summary_; }

private:
  SolveSummary summary_;
};

/// The operator A on one rank's padded block: `apply(x, y)` with x a padded array whose halos
/// have been exchanged and y a zero-filled padded array; it writes (A x) into y's own cells,
/// typically by calling a halo kernel. For the transpose, `apply_transpose(v, w)` gets a seed v
/// (its own cells hold the vector, its halos 0) and must ADD the kernel's transpose applied to v
/// into the zero-filled w, halos included, as the kernel's generated adjoint with respect to its
/// input does (`kernel_adjoint(x, w, ..., v, ...)`); the solver then sends w's halos back
/// (mpi::exchange_halos_adjoint).
using PaddedOperator = std::function<void(const Eigen::VectorXd& in, Eigen::VectorXd& out)>;

namespace detail {

inline void check(PetscErrorCode code, const std::string& where, const char* call) {
  if (code != 0)
    throw std::runtime_error(
        dpgen::detail::message(where, ": PETSc error ", static_cast<int>(code), " in ", call));
}

// Colours for probing a stencil of radius r along a dimension of n cells: cells of the same
// colour must be at least 2r + 1 apart, so that no row of A reaches two of them. Colour
// g mod m with m >= 2r + 1; in a periodic dimension m must also divide n, so that the colours
// agree across the wrap (m = n, every cell its own colour, when nothing smaller fits).
inline int probe_colours(int n, int r, bool periodic) {
  const int m = std::min(2 * r + 1, n);
  if (!periodic)
    return m;
  for (int c = m; c < n; ++c)
    if (n % c == 0)
      return c;
  return n;
}

} // namespace detail

/// Solves A x = b (and A^T lambda = x_bar) for an operator given as a kernel on the padded
/// blocks of a decomposition, with PETSc. Vectors in and out are interior vectors (this rank's
/// own cells, Decomposition::interior_size()). Every method is collective over the
/// decomposition's communicator, and the decomposition must outlive the solver.
///
/// A is a MatShell: its mult copies x into a padded array, exchanges the halos, runs `apply`,
/// and takes the interior of the result; its transpose mult runs `apply_transpose` and the
/// reverse halo exchange. The preconditioner (BoomerAMG, GAMG, Jacobi) needs an assembled
/// matrix: the solver builds one by probing the MatShell with one vector per colour class (9
/// products for a 5-point stencil on a periodic grid of multiples of 3), exact for any linear
/// kernel of the given stencil radius. After the operator's coefficients change, call
/// update_operator() so that the assembled copy follows.
class LinearSolver {
public:
  LinearSolver(const mpi::Decomposition& dec, PaddedOperator apply, SolverOptions options = {},
               PaddedOperator apply_transpose = {})
      : dec_(dec), apply_(std::move(apply)), apply_transpose_(std::move(apply_transpose)),
        options_(std::move(options)) {
    const std::string& w = options_.name;
    if (!apply_)
      throw std::invalid_argument(
          dpgen::detail::message(dec_.where(), ": ", w, ": no operator given"));
    if (!options_.symmetric && !apply_transpose_)
      throw std::invalid_argument(dpgen::detail::message(
          dec_.where(), ": ", w, ": a non-symmetric operator needs apply_transpose"));
    if (options_.stencil_radius < 1 || options_.stencil_radius > dec_.halo())
      throw std::invalid_argument(dpgen::detail::message(
          dec_.where(), ": ", w, ": stencil radius ", options_.stencil_radius,
          " must be between 1 and the halo width ", dec_.halo()));
    if (options_.max_iterations < 0 || !(options_.relative_tolerance >= 0) ||
        !(options_.absolute_tolerance >= 0))
      throw std::invalid_argument(dpgen::detail::message(
          dec_.where(), ": ", w, ": need max_iterations >= 0 and tolerances >= 0"));
    Preconditioner pc = options_.preconditioner;
    if (pc == Preconditioner::automatic)
      pc = !options_.symmetric ? Preconditioner::jacobi
           : has_hypre()       ? Preconditioner::boomeramg
                               : Preconditioner::gamg;
    if (pc == Preconditioner::boomeramg && !has_hypre())
      throw std::invalid_argument(dpgen::detail::message(
          dec_.where(), ": ", w, ": BoomerAMG requested, but this PETSc has no hypre"));
    pc_ = pc;

    const PetscInt n = static_cast<PetscInt>(dec_.interior_size());
    const PetscInt N = static_cast<PetscInt>(dec_.global_size());
    const MPI_Comm comm = dec_.comm();
    detail::check(MatCreateShell(comm, n, n, N, N, this, &a_), where(), "MatCreateShell");
    detail::check(MatShellSetOperation(a_, MATOP_MULT, (void (*)(void)) & LinearSolver::shell_mult),
                  where(), "MatShellSetOperation");
    if (apply_transpose_)
      detail::check(MatShellSetOperation(a_, MATOP_MULT_TRANSPOSE,
                                         (void (*)(void)) & LinearSolver::shell_mult_transpose),
                    where(), "MatShellSetOperation");
    detail::check(VecCreateMPI(comm, n, N, &b_), where(), "VecCreateMPI");
    detail::check(VecDuplicate(b_, &x_), where(), "VecDuplicate");
    if (options_.constant_null_space) {
      detail::check(MatNullSpaceCreate(comm, PETSC_TRUE, 0, nullptr, &null_space_), where(),
                    "MatNullSpaceCreate");
      detail::check(MatSetNullSpace(a_, null_space_), where(), "MatSetNullSpace");
      detail::check(MatSetTransposeNullSpace(a_, null_space_), where(), "MatSetTransposeNullSpace");
    }
    // PETSc's global numbering: rank r owns the rows starts_[r] .. starts_[r+1]-1, its cells x
    // fastest, in rank order of the decomposition's communicator.
    starts_.assign(static_cast<std::size_t>(dec_.size()) + 1, 0);
    std::vector<int> counts(static_cast<std::size_t>(dec_.size()));
    const int mine = static_cast<int>(n);
    MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    for (int r = 0; r < dec_.size(); ++r)
      starts_[r + 1] = starts_[r] + counts[r];

    detail::check(KSPCreate(comm, &ksp_), where(), "KSPCreate");
    if (!options_.options_prefix.empty())
      detail::check(KSPSetOptionsPrefix(ksp_, options_.options_prefix.c_str()), where(),
                    "KSPSetOptionsPrefix");
    PC pcx = nullptr;
    detail::check(KSPGetPC(ksp_, &pcx), where(), "KSPGetPC");
    if (options_.symmetric) {
      detail::check(KSPSetType(ksp_, KSPCG), where(), "KSPSetType");
      detail::check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), where(), "KSPSetNormType");
    } else {
      detail::check(KSPSetType(ksp_, KSPGMRES), where(), "KSPSetType");
      detail::check(KSPSetPCSide(ksp_, PC_RIGHT), where(), "KSPSetPCSide");
      detail::check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), where(), "KSPSetNormType");
    }
    switch (pc_) {
    case Preconditioner::boomeramg:
      detail::check(PCSetType(pcx, PCHYPRE), where(), "PCSetType(hypre)");
      detail::check(PCHYPRESetType(pcx, "boomeramg"), where(), "PCHYPRESetType");
      pc_name_ = "hypre boomeramg";
      break;
    case Preconditioner::gamg:
      detail::check(PCSetType(pcx, PCGAMG), where(), "PCSetType(gamg)");
      pc_name_ = "gamg";
      break;
    case Preconditioner::jacobi:
      detail::check(PCSetType(pcx, PCJACOBI), where(), "PCSetType(jacobi)");
      pc_name_ = "jacobi";
      break;
    default:
      detail::check(PCSetType(pcx, PCNONE), where(), "PCSetType(none)");
      pc_name_ = "none";
      break;
    }
    detail::check(KSPSetTolerances(ksp_, options_.relative_tolerance, options_.absolute_tolerance,
                                   PETSC_DEFAULT, options_.max_iterations),
                  where(), "KSPSetTolerances");
    update_operator();
    // BoomerAMG solves its coarsest level directly by default; with a constant null space that
    // matrix is singular and the preconditioner can come out indefinite (CG then stops with
    // DIVERGED_INDEFINITE_PC, seen on a 256 x 128 periodic Poisson). Relax on the coarsest
    // level instead, unless the user's options say otherwise. Set for this KSP's
    // KSPSetFromOptions only, then taken out of PETSc's options database again.
    const std::string coarse =
        "-" + options_.options_prefix + "pc_hypre_boomeramg_relax_type_coarse";
    PetscBool user_set = PETSC_FALSE;
    detail::check(PetscOptionsHasName(nullptr, nullptr, coarse.c_str(), &user_set), where(),
                  "PetscOptionsHasName");
    const bool relax_coarse =
        pc_ == Preconditioner::boomeramg && options_.constant_null_space && !user_set;
    if (relax_coarse)
      detail::check(PetscOptionsSetValue(nullptr, coarse.c_str(), "symmetric-SOR/Jacobi"), where(),
                    "PetscOptionsSetValue");
    const PetscErrorCode code = KSPSetFromOptions(ksp_);
    if (relax_coarse)
      PetscOptionsClearValue(nullptr, coarse.c_str());
    detail::check(code, where(), "KSPSetFromOptions");
  }

  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;
  ~LinearSolver() {
    KSPDestroy(&ksp_);
    MatDestroy(&p_);
    MatDestroy(&a_);
    VecDestroy(&x_);
    VecDestroy(&b_);
    if (null_space_)
      MatNullSpaceDestroy(&null_space_);
  }

  /// Rebuilds the preconditioner's assembled copy of A by probing (after A's coefficients
  /// changed) and hands both to the KSP. Without a preconditioner only the latter.
  void update_operator() {
    if (pc_ != Preconditioner::none)
      probe();
    detail::check(KSPSetOperators(ksp_, a_, p_ ? p_ : a_), where(), "KSPSetOperators");
  }

  /// Solves A x = b; `x` is the solution on return (mean-free with a constant null space).
  /// The initial guess works as in dpgen::conjugate_gradient: the optional `initial_guess`
  /// (this rank's block; it may be `&x`), or zero when null, the incoming `x` being ignored
  /// then. Throws SolveError on every rank when the solve does not converge (and
  /// options.throw_on_failure).
  SolveSummary solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                     const Eigen::VectorXd* initial_guess = nullptr) {
    return run(b, x, initial_guess, false, false);
  }

  /// Solves A^T lambda = x_bar: the same solve for a symmetric operator, KSPSolveTranspose
  /// otherwise. `lambda` and `initial_guess` as `x` and `initial_guess` in solve().
  SolveSummary solve_transpose(const Eigen::VectorXd& x_bar, Eigen::VectorXd& lambda,
                               const Eigen::VectorXd* initial_guess = nullptr) {
    return run(x_bar, lambda, initial_guess, true, !options_.symmetric);
  }

  /// y = A x and w = A^T v on interior vectors (through the MatShell; for tests and checks).
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) { multiply(x, y, false); }
  void apply_transpose(const Eigen::VectorXd& v, Eigen::VectorXd& w) {
    if (options_.symmetric && !apply_transpose_)
      multiply(v, w, false);
    else
      multiply(v, w, true);
  }

  /// The preconditioner in use, e.g. "hypre boomeramg", "gamg", "jacobi", "none".
  const std::string& preconditioner_name() const { return pc_name_; }
  /// PETSc's objects, for inspection or extra settings.
  Mat shell() const { return a_; }
  Mat assembled() const { return p_; }
  KSP ksp() const { return ksp_; }
  const mpi::Decomposition& decomposition() const { return dec_; }

private:
  std::string where() const { return dec_.where() + ": " + options_.name; }

  // x (interior) -> y = A x (interior), through the padded kernel.
  void padded_mult(const double* x, double* y, bool transpose) {
    const Eigen::Index n = dec_.interior_size();
    Eigen::Map<const Eigen::VectorXd> xin(x, n);
    in_.setZero(dec_.padded_size());
    dec_.copy_interior(xin, in_);
    out_.setZero(dec_.padded_size());
    if (!transpose) {
      mpi::exchange_halos(dec_, in_); // the kernel reads its neighbours' cells
      apply_(in_, out_);
    } else {
      apply_transpose_(in_, out_);             // adjoints land in w's own cells and halos
      mpi::exchange_halos_adjoint(dec_, out_); // halo adjoints back to their owners
    }
    dec_.require_size(out_.size(), dec_.padded_size(), options_.name + ": operator output",
                      "padded block");
    Eigen::Map<Eigen::VectorXd>(y, n) = dec_.interior(out_);
  }

  static PetscErrorCode shell_mult(Mat a, Vec x, Vec y) { return shell(a, x, y, false); }
  static PetscErrorCode shell_mult_transpose(Mat a, Vec x, Vec y) { return shell(a, x, y, true); }
  static PetscErrorCode shell(Mat a, Vec x, Vec y, bool transpose) {
    void* context = nullptr;
    if (MatShellGetContext(a, &context) != 0)
      return PETSC_ERR_LIB;
    auto* self = static_cast<LinearSolver*>(context);
    const PetscScalar* xa = nullptr;
    PetscScalar* ya = nullptr;
    if (VecGetArrayRead(x, &xa) != 0 || VecGetArray(y, &ya) != 0)
      return PETSC_ERR_LIB;
    PetscErrorCode code = 0;
    try { // no exception may cross PETSc's C frames: keep it, rethrow after KSPSolve
      self->padded_mult(xa, ya, transpose);
    } catch (...) {
      self->error_ = std::current_exception();
      code = PETSC_ERR_USER;
    }
    VecRestoreArrayRead(x, &xa);
    VecRestoreArray(y, &ya);
    return code;
  }

  void rethrow_or(PetscErrorCode code, const char* call) {
    if (error_) {
      std::exception_ptr e = error_;
      error_ = nullptr;
      std::rethrow_exception(e);
    }
    detail::check(code, where(), call);
  }

  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y, bool transpose) {
    dec_.require_size(x.size(), dec_.interior_size(), options_.name + ": vector", "block");
    set(b_, x);
    const PetscErrorCode code = transpose ? MatMultTranspose(a_, b_, x_) : MatMult(a_, b_, x_);
    rethrow_or(code, transpose ? "MatMultTranspose" : "MatMult");
    get(x_, y);
  }

  void set(Vec v, const Eigen::VectorXd& e) {
    PetscScalar* a = nullptr;
    detail::check(VecGetArray(v, &a), where(), "VecGetArray");
    Eigen::Map<Eigen::VectorXd>(a, e.size()) = e;
    detail::check(VecRestoreArray(v, &a), where(), "VecRestoreArray");
  }
  void get(Vec v, Eigen::VectorXd& e) {
    const PetscScalar* a = nullptr;
    e.resize(dec_.interior_size());
    detail::check(VecGetArrayRead(v, &a), where(), "VecGetArrayRead");
    e = Eigen::Map<const Eigen::VectorXd>(a, e.size());
    detail::check(VecRestoreArrayRead(v, &a), where(), "VecRestoreArrayRead");
  }

  // The solve A x = rhs (backward: A^T lambda = x_bar, by KSPSolveTranspose when `transpose`).
  SolveSummary run(const Eigen::VectorXd& rhs, Eigen::VectorXd& x,
                   const Eigen::VectorXd* initial_guess, bool backward, bool transpose) {
    const std::string what =
        options_.name + (backward ? " backward (A^T lambda = x_bar)" : " forward (A x = b)");
    dec_.require_size(rhs.size(), dec_.interior_size(), what + ": right-hand side", "block");
    dpgen::detail::require_finite(rhs, dec_.where() + ": " + what, "right-hand side");
    set(b_, rhs);
    if (null_space_) // only the part of b orthogonal to the constants is solvable
      detail::check(MatNullSpaceRemove(null_space_, b_), where(), "MatNullSpaceRemove");
    const bool use_initial_guess = initial_guess != nullptr;
    if (use_initial_guess) {
      dec_.require_size(initial_guess->size(), dec_.interior_size(), what + ": initial guess",
                        "block");
      dpgen::detail::require_finite(*initial_guess, dec_.where() + ": " + what, "initial guess");
      set(x_, *initial_guess);
    } else {
      detail::check(VecSet(x_, 0.0), where(), "VecSet");
    }
    detail::check(KSPSetInitialGuessNonzero(ksp_, use_initial_guess ? PETSC_TRUE : PETSC_FALSE),
                  where(), "KSPSetInitialGuessNonzero");
    const PetscErrorCode code =
        transpose ? KSPSolveTranspose(ksp_, b_, x_) : KSPSolve(ksp_, b_, x_);
    rethrow_or(code, transpose ? "KSPSolveTranspose" : "KSPSolve");
    if (null_space_) // the mean-free representative of the solution set
      detail::check(MatNullSpaceRemove(null_space_, x_), where(), "MatNullSpaceRemove");
    get(x_, x);

    SolveSummary s;
    PetscInt its = 0;
    PetscReal rnorm = 0, bnorm = 0;
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    detail::check(KSPGetIterationNumber(ksp_, &its), where(), "KSPGetIterationNumber");
    detail::check(KSPGetResidualNorm(ksp_, &rnorm), where(), "KSPGetResidualNorm");
    detail::check(KSPGetConvergedReason(ksp_, &reason), where(), "KSPGetConvergedReason");
    detail::check(VecNorm(b_, NORM_2, &bnorm), where(), "VecNorm");
    s.iterations = static_cast<int>(its);
    s.residual_norm = rnorm;
    s.rhs_norm = bnorm;
    s.tolerance = std::max(options_.relative_tolerance * bnorm, options_.absolute_tolerance);
    s.reason = static_cast<int>(reason);
    s.reason_name = KSPConvergedReasons[reason];
    s.preconditioner = pc_name_;
    const char* method = options_.symmetric ? "CG" : "GMRES";
    if (s.converged())
      s.message = dpgen::detail::message(
          what, ": ", method, " + ", pc_name_, " converged (", s.reason_name, ") in ", s.iterations,
          " iterations, residual ", rnorm, " <= tolerance ", s.tolerance);
    else
      s.message =
          dpgen::detail::message(what, ": ", method, " + ", pc_name_, " did not converge (",
                                 s.reason_name, ") after ", s.iterations, " iterations, residual ",
                                 rnorm, " > tolerance ", s.tolerance, " (||b|| = ", bnorm, ")");
    if (!s.converged() && options_.throw_on_failure)
      throw SolveError(s);
    return s;
  }

  // The assembled copy of A by probing. With colour classes C (detail::probe_colours per
  // dimension), A e_C (e_C: 1 on the cells of class C) holds, in row i, sum over j in C of
  // A_ij; at most one j in C lies within the stencil of i, so that sum is A_ij itself for the
  // j of class C next to i. One product per class gives every entry.
  void probe() {
    const int r = options_.stencil_radius, dims = dec_.dims();
    std::array<int, 3> colours{1, 1, 1};
    for (int d = 0; d < dims; ++d)
      colours[d] = detail::probe_colours(dec_.global(d), r, dec_.periodic(d));
    const PetscInt n = static_cast<PetscInt>(dec_.interior_size());
    const PetscInt N = static_cast<PetscInt>(dec_.global_size());
    PetscInt width = 1;
    for (int d = 0; d < dims; ++d)
      width *= 2 * r + 1;
    if (!p_) {
      detail::check(MatCreateAIJ(dec_.comm(), n, n, N, N, width, nullptr, width, nullptr, &p_),
                    where(), "MatCreateAIJ");
      if (null_space_)
        detail::check(MatSetNullSpace(p_, null_space_), where(), "MatSetNullSpace");
    }
    const std::array<int, 3> lo{-r, dims > 1 ? -r : 0, dims > 2 ? -r : 0};
    const std::array<int, 3> hi{r, dims > 1 ? r : 0, dims > 2 ? r : 0};
    Eigen::VectorXd e(dec_.interior_size()), ae;
    std::vector<PetscInt> cols;
    for (int c2 = 0; c2 < colours[2]; ++c2)
      for (int c1 = 0; c1 < colours[1]; ++c1)
        for (int c0 = 0; c0 < colours[0]; ++c0) {
          const std::array<int, 3> colour{c0, c1, c2};
          auto in_class = [&](const std::array<int, 3>& g) {
            for (int d = 0; d < 3; ++d)
              if (g[d] % colours[d] != colour[d])
                return false;
            return true;
          };
          dec_.for_each_row([&](Eigen::Index flat, Eigen::Index, int j, int k) {
            for (int i = 0; i < dec_.local(0); ++i)
              e[flat + i] = in_class({dec_.offset(0) + i, dec_.offset(1) + j, dec_.offset(2) + k})
                                ? 1.0
                                : 0.0;
          });
          multiply(e, ae, false);
          dec_.for_each_row([&](Eigen::Index flat, Eigen::Index, int j, int k) {
            for (int i = 0; i < dec_.local(0); ++i) {
              const std::array<int, 3> g{dec_.offset(0) + i, dec_.offset(1) + j,
                                         dec_.offset(2) + k};
              const PetscInt row = starts_[dec_.rank()] + static_cast<PetscInt>(flat + i);
              for (int o2 = lo[2]; o2 <= hi[2]; ++o2)
                for (int o1 = lo[1]; o1 <= hi[1]; ++o1)
                  for (int o0 = lo[0]; o0 <= hi[0]; ++o0) {
                    std::array<int, 3> h{g[0] + o0, g[1] + o1, g[2] + o2};
                    if (!wrap(h) || !in_class(h))
                      continue;
                    const PetscInt col = global_row(h);
                    const PetscScalar value = ae[flat + i];
                    detail::check(MatSetValues(p_, 1, &row, 1, &col, &value, INSERT_VALUES),
                                  where(), "MatSetValues");
                  }
            }
          });
        }
    detail::check(MatAssemblyBegin(p_, MAT_FINAL_ASSEMBLY), where(), "MatAssemblyBegin");
    detail::check(MatAssemblyEnd(p_, MAT_FINAL_ASSEMBLY), where(), "MatAssemblyEnd");
  }

  // Wraps a global cell position into the grid (periodic dimensions); false when it lies
  // outside a non-periodic one.
  bool wrap(std::array<int, 3>& g) const {
    for (int d = 0; d < dec_.dims(); ++d) {
      const int n = dec_.global(d);
      if (g[d] < 0 || g[d] >= n) {
        if (!dec_.periodic(d))
          return false;
        g[d] = ((g[d] % n) + n) % n;
      }
    }
    return true;
  }

  // PETSc's row of global cell g: its owner's first row plus its index in the owner's block.
  PetscInt global_row(const std::array<int, 3>& g) const {
    std::array<int, 3> owner{0, 0, 0}, at{0, 0, 0}, extent{1, 1, 1};
    for (int d = 0; d < dec_.dims(); ++d) {
      const int q = dec_.global(d) / dec_.processes(d), rem = dec_.global(d) % dec_.processes(d);
      const int big = rem * (q + 1); // cells in the blocks of q + 1
      owner[d] = g[d] < big ? g[d] / (q + 1) : rem + (g[d] - big) / q;
      at[d] = g[d] - dec_.block_offset(d, owner[d]);
      extent[d] = dec_.block_extent(d, owner[d]);
    }
    int rank = 0;
    MPI_Cart_rank(dec_.comm(), owner.data(), &rank);
    return starts_[rank] +
           static_cast<PetscInt>(
               (static_cast<Eigen::Index>(at[2]) * extent[1] + at[1]) * extent[0] + at[0]);
  }

  const mpi::Decomposition& dec_;
  PaddedOperator apply_, apply_transpose_;
  SolverOptions options_;
  Preconditioner pc_ = Preconditioner::none;
  std::string pc_name_;
  std::vector<PetscInt> starts_;
  Mat a_ = nullptr, p_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr;
  KSP ksp_ = nullptr;
  MatNullSpace null_space_ = nullptr;
  Eigen::VectorXd in_, out_;
  std::exception_ptr error_;
};

} // namespace dpgen::petsc
