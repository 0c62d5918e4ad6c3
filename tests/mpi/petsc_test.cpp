// Tests of dpgen/petsc: the MatShell of a halo kernel and its probed assembled copy, distributed
// CG solves and their implicit gradients against the single-process dpgen CG (periodic
// variable-coefficient Poisson) and against a dense solve and finite differences (a
// non-symmetric operator, backward by KSPSolveTranspose); non-convergence and bad input.
// Run under mpirun with 1, 2 and 4 ranks (ctest: mpi.petsc.np*).
#include "dpgen/implicit_solve.hpp"
#include "dpgen/petsc/implicit_solve.hpp"
#include "dpgen/petsc/linear_solver.hpp"

#include "halo_kernels.hpp"
#include "kernels.hpp"
#include "neg_div_k_grad_halo2d_adjoint.hpp"
#include "neg_div_k_grad_periodic2d_adjoint.hpp"
#include "neg_laplacian_halo2d_adjoint.hpp"
#include "neg_laplacian_halo3d_adjoint.hpp"
#include "operators.hpp"
#include "upwind_step_adjoint.hpp"
#include "upwind_step_halo_adjoint.hpp"

#include "mpi_test_support.hpp"

#include <Eigen/Dense>
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using dpgen::mpi::Decomposition;
using dpgen::petsc::LinearSolver;
using dpgen::petsc::Preconditioner;
using dpgen::petsc::SolverOptions;
using dpgen_mpi_test::contains;
using dpgen_mpi_test::error_of;
using dpgen_mpi_test::max_over_ranks;
using dpgen_mpi_test::random_vector;
using Eigen::VectorXd;

double relative_error(const VectorXd& a, const VectorXd& ref) {
  return max_over_ranks((a - ref).cwiseAbs().maxCoeff()) /
         max_over_ranks(ref.cwiseAbs().maxCoeff());
}

// -div(k grad p), periodic, on an nx-by-ny grid: k on the decomposition (padded, exchanged).
struct VarCoefPoisson {
  const Decomposition& dec;
  VectorXd k; // padded, halos exchanged
  double h;
  VarCoefPoisson(const Decomposition& d, const VectorXd& k_global, double h_)
      : dec(d), k(d.pad(d.local_part(k_global))), h(h_) {
    dpgen::mpi::exchange_halos(dec, k);
  }
  void apply(const VectorXd& p, VectorXd& out) const {
    neg_div_k_grad_halo2d(p.data(), k.data(), out.data(), dec.local(0), dec.local(1), h);
  }
  // d(A(k) p)/dk ^T lambda, added into g (padded)
  void k_adjoint(const VectorXd& p, const VectorXd& lambda, VectorXd& g) const {
    VectorXd p_adj = VectorXd::Zero(dec.padded_size());
    neg_div_k_grad_halo2d_adjoint(p.data(), p_adj.data(), k.data(), g.data(), lambda.data(),
                                  dec.local(0), dec.local(1), h);
  }
};

SolverOptions poisson_options(Preconditioner pc, double tol = 1e-13) {
  SolverOptions o;
  o.name = "poisson";
  o.relative_tolerance = tol;
  o.preconditioner = pc;
  o.constant_null_space = true;
  return o;
}

// The assembled copy and the MatShell agree on random vectors.
void check_probe(LinearSolver& solver, unsigned seed) {
  Vec x = nullptr, y_shell = nullptr, y_assembled = nullptr;
  MatCreateVecs(solver.shell(), &x, &y_shell);
  VecDuplicate(y_shell, &y_assembled);
  PetscRandom rng = nullptr;
  PetscRandomCreate(solver.decomposition().comm(), &rng);
  PetscRandomSetSeed(rng, seed);
  PetscRandomSeed(rng);
  VecSetRandom(x, rng);
  MatMult(solver.shell(), x, y_shell);
  MatMult(solver.assembled(), x, y_assembled);
  PetscReal ref = 0, diff = 0;
  VecNorm(y_shell, NORM_INFINITY, &ref);
  VecAXPY(y_assembled, -1.0, y_shell);
  VecNorm(y_assembled, NORM_INFINITY, &diff);
  CHECK(diff <= 1e-13 * ref);
  CHECK(ref > 0);
  PetscRandomDestroy(&rng);
  VecDestroy(&x);
  VecDestroy(&y_shell);
  VecDestroy(&y_assembled);
}

} // namespace

TEST_CASE("the probed assembled copy equals the MatShell (2D periodic, 3D, 1D non-symmetric)") {
  // 10 x 7 cells: probing colours 5 x 7 (periodic: the colour count must divide the size)
  const VectorXd k = random_vector(70, 1, 0.5, 2.0);
  Decomposition dec2(MPI_COMM_WORLD, {{10, 7}, {true, true}, {}, 1});
  VarCoefPoisson poisson(dec2, k, 0.1);
  LinearSolver s2(
      dec2, [&](const VectorXd& x, VectorXd& y) { poisson.apply(x, y); },
      poisson_options(Preconditioner::jacobi));
  check_probe(s2, 3);

  Decomposition dec3(MPI_COMM_WORLD, {{6, 5, 4}, {true, false, true}, {}, 1});
  auto lap3 = [&](const VectorXd& x, VectorXd& y) {
    neg_laplacian_halo3d(x.data(), y.data(), dec3.padded(0), dec3.padded(1), dec3.padded(2), 1.0);
  };
  LinearSolver s3(dec3, lap3, poisson_options(Preconditioner::gamg));
  check_probe(s3, 4);

  Decomposition dec1(MPI_COMM_WORLD, {{29}, {true}, {}, 1});
  VectorXd u = dec1.pad(dec1.local_part(random_vector(29, 2, -1.0, 1.0)));
  dpgen::mpi::exchange_halos(dec1, u);
  SolverOptions o;
  o.symmetric = false;
  LinearSolver s1(
      dec1,
      [&](const VectorXd& x, VectorXd& y) {
        upwind_step_halo(x.data(), u.data(), y.data(), dec1.local(0), 0.01, 1.0 / 29);
      },
      o,
      [&](const VectorXd& v, VectorXd& w) {
        VectorXd x = VectorXd::Zero(v.size()), u_adj = VectorXd::Zero(v.size());
        upwind_step_halo_adjoint(x.data(), w.data(), u.data(), u_adj.data(), v.data(),
                                 dec1.local(0), 0.01, 1.0 / 29);
      });
  check_probe(s1, 5);
}

TEST_CASE("periodic variable-coefficient Poisson: solution and implicit gradients equal the "
          "single-process dpgen CG, for every preconditioner") {
  const int nx = 12, ny = 9, n = nx * ny;
  const double h = 1.0 / nx;
  const VectorXd k = random_vector(n, 11, 0.5, 2.0);
  const VectorXd b = random_vector(n, 12), w = random_vector(n, 13);
  // L(k, b) = <w, x> + |x|^2 / 2 with A(k) x = b, so x_bar = w + x.

  // single process: the periodic-wrap kernel, dpgen's CG, the implicit rule
  dpgen::CgOptions cg;
  cg.relative_tolerance = 1e-13;
  cg.max_iterations = 5000;
  cg.remove_null_space_mean = true;
  auto a = [&](const VectorXd& x, VectorXd& y) {
    neg_div_k_grad_periodic2d(x.data(), k.data(), y.data(), nx, ny, h);
  };
  const VectorXd x_ref = dpgen::solve_forward(a, b, cg).solution;
  VectorXd b_bar_ref, k_bar_ref = VectorXd::Zero(n);
  dpgen::implicit_solve_backward(
      a,
      [&](const VectorXd& x, const VectorXd& lambda, VectorXd& g) {
        VectorXd scratch = VectorXd::Zero(n);
        neg_div_k_grad_periodic2d_adjoint(x.data(), scratch.data(), k.data(), g.data(),
                                          lambda.data(), nx, ny, h);
      },
      x_ref, w + x_ref, b_bar_ref, k_bar_ref, cg);

  Decomposition dec(MPI_COMM_WORLD, {{nx, ny}, {true, true}, {}, 1});
  VarCoefPoisson poisson(dec, k, h);
  const std::vector<Preconditioner> pcs = {Preconditioner::automatic, Preconditioner::boomeramg,
                                           Preconditioner::gamg, Preconditioner::jacobi,
                                           Preconditioner::none};
  std::vector<int> iterations;
  for (Preconditioner pc : pcs) {
    if (pc == Preconditioner::boomeramg && !dpgen::petsc::has_hypre())
      continue;
    LinearSolver solver(
        dec, [&](const VectorXd& x, VectorXd& y) { poisson.apply(x, y); }, poisson_options(pc));
    CAPTURE(solver.preconditioner_name());
    VectorXd x;
    const auto forward = solver.solve(dec.local_part(b), x);
    CHECK(forward.converged());
    CHECK(forward.residual_norm <= forward.tolerance);
    CHECK(relative_error(x, dec.local_part(x_ref)) <= 1e-10);
    CHECK(std::abs(dec.sum(x.sum())) <= 1e-12); // mean-free, as the single-process solve
    // The initial guess is the optional pointer (here x itself, already the solution) ...
    VectorXd warm = x;
    const auto restarted = solver.solve(dec.local_part(b), warm, &warm);
    CHECK(restarted.converged());
    CHECK((restarted.iterations < forward.iterations || forward.iterations <= 1));
    CHECK(relative_error(warm, x) <= 1e-10);
    // ... and without it the incoming contents are ignored: the cold solve's iterations again.
    VectorXd ignored = VectorXd::Constant(x.size(), 1e3);
    CHECK(solver.solve(dec.local_part(b), ignored).iterations == forward.iterations);

    VectorXd lambda, b_bar, k_bar = VectorXd::Zero(dec.interior_size());
    const VectorXd x_bar = dec.local_part(w) + x;
    const auto backward = dpgen::petsc::implicit_solve_backward(
        solver,
        [&](const VectorXd& xp, const VectorXd& lp, VectorXd& g) { poisson.k_adjoint(xp, lp, g); },
        x, x_bar, lambda, b_bar, k_bar);
    CHECK(backward.converged());
    CHECK(relative_error(b_bar, dec.local_part(b_bar_ref)) <= 1e-9);
    CHECK(relative_error(k_bar, dec.local_part(k_bar_ref)) <= 1e-9);
    iterations.push_back(forward.iterations);
    if (pc == Preconditioner::automatic) {
      CHECK(solver.preconditioner_name() ==
            (dpgen::petsc::has_hypre() ? "hypre boomeramg" : "gamg"));
      if (dec.rank() == 0)
        MESSAGE("automatic preconditioner: ", solver.preconditioner_name(), " (PETSc ",
                (dpgen::petsc::has_hypre() ? "has" : "lacks"), " hypre); ", forward.message);
    }
  }
  // multigrid needs fewer iterations than plain CG (a check that the preconditioner acts)
  CHECK(iterations.front() < iterations.back());
}

TEST_CASE("non-symmetric operator: GMRES forward, KSPSolveTranspose backward, gradients against "
          "a dense single-process solve and finite differences") {
  // A(u) x = upwind_step(x; u): x - dt (up (x[i+1] - x[i]) + um (x[i] - x[i-1])), periodic.
  const int n = 29;
  const double dx = 1.0 / n, dt = 0.3 * dx;
  const VectorXd u = random_vector(n, 21, -1.0, 1.0), b = random_vector(n, 22);
  const VectorXd w = random_vector(n, 23);
  // L(u, b) = <w, x>: x_bar = w.

  // single process, dense: A's columns from the serial periodic kernel, LU solves
  Eigen::MatrixXd dense(n, n);
  for (int j = 0; j < n; ++j) {
    VectorXd e = VectorXd::Unit(n, j), col(n);
    upwind_step(e.data(), u.data(), col.data(), n, dt, dx);
    dense.col(j) = col;
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(dense);
  const VectorXd x_ref = lu.solve(b);
  const VectorXd lambda_ref = lu.transpose().solve(w);
  VectorXd u_bar_ref = VectorXd::Zero(n), scratch = VectorXd::Zero(n);
  upwind_step_adjoint(x_ref.data(), scratch.data(), u.data(), u_bar_ref.data(), lambda_ref.data(),
                      n, dt, dx);
  u_bar_ref = -u_bar_ref; // u_bar = -(d(A x)/du)^T lambda

  Decomposition dec(MPI_COMM_WORLD, {{n}, {true}, {}, 1});
  // the distributed loss and gradient at velocity u_global
  auto solve = [&](const VectorXd& u_global, VectorXd* u_bar, VectorXd* b_bar) {
    VectorXd up = dec.pad(dec.local_part(u_global));
    dpgen::mpi::exchange_halos(dec, up);
    const int nl = dec.local(0);
    SolverOptions o;
    o.name = "upwind";
    o.symmetric = false;
    o.relative_tolerance = 1e-14;
    LinearSolver solver(
        dec,
        [&](const VectorXd& x, VectorXd& y) {
          upwind_step_halo(x.data(), up.data(), y.data(), nl, dt, dx);
        },
        o,
        [&](const VectorXd& v, VectorXd& wt) {
          VectorXd x0 = VectorXd::Zero(v.size()), u_adj = VectorXd::Zero(v.size());
          upwind_step_halo_adjoint(x0.data(), wt.data(), up.data(), u_adj.data(), v.data(), nl, dt,
                                   dx);
        });
    CHECK(solver.preconditioner_name() == "jacobi");
    // dot-product test of the MatShell's transpose: <A x, y> = <x, A^T y>
    const VectorXd xr = random_vector(dec.interior_size(), 30 + dec.rank());
    const VectorXd yr = random_vector(dec.interior_size(), 40 + dec.rank());
    VectorXd ax, aty;
    solver.apply(xr, ax);
    solver.apply_transpose(yr, aty);
    CHECK(std::abs(dec.dot(ax, yr) - dec.dot(xr, aty)) <= 1e-13 * std::abs(dec.dot(ax, yr)));

    VectorXd x;
    solver.solve(dec.local_part(b), x);
    if (u_bar) {
      CHECK(relative_error(x, dec.local_part(x_ref)) <= 1e-12);
      VectorXd lambda;
      *u_bar = VectorXd::Zero(dec.interior_size());
      const auto back = dpgen::petsc::implicit_solve_backward(
          solver,
          [&](const VectorXd& xp, const VectorXd& lp, VectorXd& g) {
            VectorXd x_adj = VectorXd::Zero(xp.size());
            upwind_step_halo_adjoint(xp.data(), x_adj.data(), up.data(), g.data(), lp.data(), nl,
                                     dt, dx);
          },
          x, dec.local_part(w), lambda, *b_bar, *u_bar);
      CHECK(back.converged());
      CHECK(contains(back.message, "GMRES + jacobi converged"));
    }
    return dec.dot(dec.local_part(w), x);
  };
  VectorXd u_bar, b_bar;
  solve(u, &u_bar, &b_bar);
  CHECK(relative_error(b_bar, dec.local_part(lambda_ref)) <= 1e-12);
  CHECK(relative_error(u_bar, dec.local_part(u_bar_ref)) <= 1e-11);
  // central differences along a random direction (L is smooth in u away from u = 0)
  const VectorXd d = random_vector(n, 24);
  const double eps = 1e-6;
  const double fd =
      (solve(u + eps * d, nullptr, nullptr) - solve(u - eps * d, nullptr, nullptr)) / (2 * eps);
  const double ad = dec.dot(u_bar, dec.local_part(d));
  CHECK(std::abs(fd - ad) <= 1e-6 * std::abs(ad));
}

TEST_CASE("BoomerAMG on a singular periodic Poisson operator converges (iterative coarse solve)") {
  // On 256 x 128 periodic cells hypre's default coarsest-level direct solve, of a singular
  // matrix, made the preconditioner indefinite (CG stopped with DIVERGED_INDEFINITE_PC); with a
  // constant null space the solver relaxes on the coarsest level instead.
  const int nx = 256, ny = 128;
  Decomposition dec(MPI_COMM_WORLD, {{nx, ny}, {true, true}, {}, 1});
  auto apply = [&](const VectorXd& x, VectorXd& y) {
    neg_laplacian_halo2d(x.data(), y.data(), dec.local(0), dec.local(1), 1.0 / nx);
  };
  LinearSolver solver(dec, apply, poisson_options(Preconditioner::boomeramg, 1e-12));
  // a smooth right-hand side (CG then runs into the round-off where the indefiniteness shows)
  VectorXd b(dec.interior_size());
  dec.for_each_row([&](Eigen::Index flat, Eigen::Index, int j, int) {
    for (int i = 0; i < dec.local(0); ++i) {
      const double x = (dec.offset(0) + i + 0.5) / nx, y = (dec.offset(1) + j + 0.5) / ny;
      b[flat + i] = std::exp(-(std::pow((x - 0.4) / 0.06, 2) + std::pow((y - 0.5) / 0.2, 2)));
    }
  });
  for (const VectorXd& rhs : {b, VectorXd(dec.local_part(random_vector(nx * ny, 51)))}) {
    VectorXd x;
    const auto s = solver.solve(rhs, x);
    CAPTURE(s.message);
    CHECK(s.converged());
    CHECK(s.iterations <= 30);
  }
}

TEST_CASE("non-convergence is an error on every rank with iterations and residual") {
  Decomposition dec(MPI_COMM_WORLD, {{12, 9}, {true, true}, {}, 1});
  VarCoefPoisson poisson(dec, random_vector(108, 31, 0.5, 2.0), 1.0 / 12);
  SolverOptions o = poisson_options(Preconditioner::none);
  o.max_iterations = 3;
  LinearSolver solver(
      dec, [&](const VectorXd& x, VectorXd& y) { poisson.apply(x, y); }, o);
  VectorXd x;
  const VectorXd b = dec.local_part(random_vector(108, 32));
  const std::string e = error_of([&] { solver.solve(b, x); });
  CAPTURE(e);
  CHECK(contains(e, "poisson forward (A x = b): CG + none did not converge (DIVERGED_ITS) after 3 "
                    "iterations, residual "));
  CHECK(contains(e, "> tolerance "));
  try {
    solver.solve(b, x);
  } catch (const dpgen::petsc::SolveError& error) {
    CHECK(error.summary().iterations == 3);
    CHECK(error.summary().residual_norm > error.summary().tolerance);
  }
  o.throw_on_failure = false;
  LinearSolver quiet(
      dec, [&](const VectorXd& x, VectorXd& y) { poisson.apply(x, y); }, o);
  CHECK_FALSE(quiet.solve(b, x).converged());
}

TEST_CASE("bad input to a distributed solver names the rank and what is wrong") {
  Decomposition dec(MPI_COMM_WORLD, {{12, 9}, {true, true}, {}, 1});
  VarCoefPoisson poisson(dec, random_vector(108, 41, 0.5, 2.0), 1.0 / 12);
  auto apply = [&](const VectorXd& x, VectorXd& y) { poisson.apply(x, y); };
  LinearSolver solver(dec, apply, poisson_options(Preconditioner::jacobi));
  VectorXd x;
  std::string e = error_of([&] { solver.solve(VectorXd::Zero(dec.interior_size() + 1), x); });
  CHECK(contains(e, dec.where() + ": poisson forward (A x = b): right-hand side has "));
  VectorXd b = VectorXd::Zero(dec.interior_size());
  b[0] = std::nan("");
  e = error_of([&] { solver.solve(b, x); });
  CHECK(contains(e, dec.where() + ": poisson forward (A x = b): right-hand side contains nan"));
  SolverOptions o = poisson_options(Preconditioner::jacobi);
  o.symmetric = false;
  e = error_of([&] { LinearSolver s(dec, apply, o); });
  CHECK(contains(e, "a non-symmetric operator needs apply_transpose"));
  o = poisson_options(Preconditioner::jacobi);
  o.stencil_radius = 2;
  e = error_of([&] { LinearSolver s(dec, apply, o); });
  CHECK(contains(e, "stencil radius 2 must be between 1 and the halo width 1"));
}
