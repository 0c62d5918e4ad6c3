// Tests of dpgen/solvers/multigrid.hpp: the V-cycle is a symmetric positive definite operator; its
// contraction factor is bounded independently of the grid size and of the number of levels;
// MG-preconditioned CG needs a flat number of iterations as the grid grows; gradients of an
// implicit solve preconditioned by it match central differences; errors are clear.
#include "dpgen/implicit_solve.hpp"
#include "dpgen/solvers/multigrid.hpp"
#include "neg_div_k_grad_periodic2d_adjoint.hpp"
#include "neg_div_k_grad_walls2d_adjoint.hpp"
#include "operators.hpp"

#include "test_support.hpp"

#include <doctest/doctest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using dpgen::Boundaries;
using dpgen::Boundary;
using dpgen_test::random_vector;
using Eigen::VectorXd;

// Wall weight of neg_div_k_grad_walls2d: 0 for Neumann, 2 for Dirichlet.
double wall(Boundary b) { return b == Boundary::dirichlet ? 2.0 : 0.0; }

// The test operator for a set of boundaries: the periodic kernel, or the walls kernel with the
// walls' weights.
dpgen::LevelOperator operator_for(const Boundaries& bc) {
  if (bc.west == Boundary::periodic)
    return neg_div_k_grad_periodic2d;
  return [bc](const double* x, const double* k, double* y, int nx, int ny, double h) {
    neg_div_k_grad_walls2d(x, k, y, nx, ny, h, wall(bc.west), wall(bc.east), wall(bc.south),
                           wall(bc.north));
  };
}

// A smooth, strongly varying coefficient in [0.2, 1.8] (a factor 9 across the domain).
VectorXd smooth_coefficient(int n) {
  VectorXd k(n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) / n, y = (j + 0.5) / n;
      k[j * n + i] = 1.0 + 0.8 * std::sin(6.283185307179586 * x) * std::cos(6.283185307179586 * y);
    }
  return k;
}

struct Case {
  std::string name;
  Boundaries bc;
};
const std::vector<Case> kCases = {
    {"periodic", Boundaries::all(Boundary::periodic)},
    {"dirichlet", Boundaries::all(Boundary::dirichlet)},
    {"neumann", Boundaries::all(Boundary::neumann)},
    // closed box with an open top, as a smoke plume's pressure has
    {"neumann + dirichlet north",
     {Boundary::neumann, Boundary::neumann, Boundary::neumann, Boundary::dirichlet}},
};

// The mean-free part, for right-hand sides of singular (null-space) problems.
VectorXd solvable(const dpgen::Multigrid& mg, VectorXd b) {
  if (mg.constant_null_space())
    b.array() -= b.mean();
  return b;
}

// Asymptotic contraction of the stationary iteration x <- x + B (b - A x): the geometric mean
// of the residual reduction per cycle over cycles 3..12 (the first two are transients).
double contraction(dpgen::Multigrid& mg, const VectorXd& b) {
  VectorXd x = VectorXd::Zero(b.size()), ax;
  auto residual = [&] {
    mg.apply(x, ax);
    return (b - ax).norm();
  };
  for (int c = 0; c < 2; ++c)
    mg.cycle(b, x);
  const double r2 = residual();
  for (int c = 2; c < 12; ++c)
    mg.cycle(b, x);
  return std::pow(residual() / r2, 1.0 / 10.0);
}

} // namespace

TEST_CASE("operator_diagonal probes the exact diagonal of 5- and 9-point stencils") {
  // A 9-point operator whose off-diagonal entries differ from cell to cell (so a wrong colouring
  // shows up): 20 + k[c] on the diagonal, -(1 + (k[c] + k[m]) / 100) to each neighbour m.
  for (bool periodic : {true, false})
    for (int nx = 1; nx <= 8; ++nx)
      for (int ny = 1; ny <= 7; ++ny) {
        CAPTURE(periodic);
        CAPTURE(nx);
        CAPTURE(ny);
        const dpgen::LevelOperator nine_point = [periodic](const double* x, const double* k,
                                                           double* y, int mx, int my, double) {
          for (int j = 0; j < my; ++j)
            for (int i = 0; i < mx; ++i) {
              double sum = (20.0 + k[j * mx + i]) * x[j * mx + i];
              for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                  int ii = i + di, jj = j + dj;
                  if (di == 0 && dj == 0)
                    continue;
                  if (periodic) {
                    ii = (ii + mx) % mx, jj = (jj + my) % my;
                  } else if (ii < 0 || ii >= mx || jj < 0 || jj >= my) {
                    continue;
                  }
                  // symmetric weight: depends on the pair of cells, not on the direction
                  const double weight = 1.0 + 0.01 * (k[j * mx + i] + k[jj * mx + ii]);
                  sum -= weight * x[jj * mx + ii];
                }
              y[j * mx + i] = sum;
            }
        };
        const VectorXd k = random_vector(nx * ny, 11, 0.5, 2.0);
        const Boundaries bc = Boundaries::all(periodic ? Boundary::periodic : Boundary::neumann);
        const VectorXd probed = dpgen::operator_diagonal(nine_point, k, nx, ny, 0.1, bc);
        VectorXd exact(nx * ny), unit = VectorXd::Zero(nx * ny), column(nx * ny);
        for (int c = 0; c < nx * ny; ++c) {
          unit[c] = 1.0;
          nine_point(unit.data(), k.data(), column.data(), nx, ny, 0.1);
          exact[c] = column[c];
          unit[c] = 0.0;
        }
        CHECK((probed - exact).cwiseAbs().maxCoeff() == 0.0);
      }
}

TEST_CASE("the V-cycle is a symmetric positive definite operator (a valid CG preconditioner)") {
  for (const Case& tc : kCases) {
    CAPTURE(tc.name);
    const int n = 32;
    dpgen::Multigrid mg(n, n, 1.0 / n, tc.bc, operator_for(tc.bc), smooth_coefficient(n));
    CHECK(mg.levels() == 3); // 32 -> 16 -> 8: the first grid with <= 64 cells
    CHECK(mg.constant_null_space() ==
          (tc.bc.west == Boundary::periodic || tc.bc.north == Boundary::neumann));
    const VectorXd r1 = solvable(mg, random_vector(n * n, 1));
    const VectorXd r2 = solvable(mg, random_vector(n * n, 2));
    VectorXd z1, z2;
    mg.precondition(r1, z1);
    mg.precondition(r2, z2);
    // <B r1, r2> = <r1, B r2> up to rounding: R = P^T / 4 exactly, Jacobi is self-adjoint.
    CHECK(z1.dot(r2) == doctest::Approx(r1.dot(z2)).epsilon(1e-12));
    CHECK(z1.dot(r1) > 0.0);
    CHECK(z2.dot(r2) > 0.0);
  }
}

TEST_CASE("V-cycle contraction is bounded independently of the grid size") {
  for (const Case& tc : kCases) {
    CAPTURE(tc.name);
    std::vector<double> rates;
    for (int n : {16, 32, 64, 128, 256}) {
      CAPTURE(n);
      dpgen::Multigrid mg(n, n, 1.0 / n, tc.bc, operator_for(tc.bc), smooth_coefficient(n));
      const double rate = contraction(mg, solvable(mg, random_vector(n * n, 3)));
      MESSAGE(tc.name, " n = ", n, " levels = ", mg.levels(), " contraction = ", rate);
      CHECK(rate < 0.3);
      rates.push_back(rate);
    }
    // More levels cost a little (16: two levels, 0.19), then the rate saturates: from 64 to
    // 256 cells a side it moves by less than 0.02.
    CHECK(std::abs(rates[4] - rates[2]) < 0.02);
    CHECK(std::abs(rates[3] - rates[2]) < 0.02);
  }
}

TEST_CASE("V-cycle contraction per level count: bounded from 2 to 6 levels") {
  const int n = 64;
  for (const Case& tc : {kCases[0], kCases[1]}) {
    CAPTURE(tc.name);
    std::vector<double> rates;
    for (int levels = 2; levels <= 6; ++levels) {
      CAPTURE(levels);
      dpgen::MultigridOptions options;
      options.levels = levels;
      options.max_coarse_cells = 32 * 32; // two levels: a direct solve on 32x32
      dpgen::Multigrid mg(n, n, 1.0 / n, tc.bc, operator_for(tc.bc), smooth_coefficient(n),
                          options);
      REQUIRE(mg.levels() == levels);
      CHECK(mg.level_nx(levels - 1) == n >> (levels - 1));
      const double rate = contraction(mg, solvable(mg, random_vector(n * n, 4)));
      MESSAGE(tc.name, " levels = ", levels, " contraction = ", rate);
      CHECK(rate < 0.35);
      rates.push_back(rate);
    }
    // The two-grid rate (0.19) grows to about 0.26 (periodic) and 0.30 (Dirichlet, whose 2x2
    // coarsest grid is a poor model of the fine one) and stays there.
    CHECK(rates.back() < rates.front() + 0.15);
  }
}

TEST_CASE("MG-preconditioned CG: iterations to 1e-8 stay flat as the grid grows") {
  for (const Case& tc : kCases) {
    CAPTURE(tc.name);
    std::vector<int> mg_iterations;
    int jacobi_iterations = 0;
    for (int n : {32, 64, 128, 256}) {
      CAPTURE(n);
      dpgen::Multigrid mg(n, n, 1.0 / n, tc.bc, operator_for(tc.bc), smooth_coefficient(n));
      dpgen::CgOptions cg;
      cg.relative_tolerance = 1e-8;
      cg.remove_null_space_mean = mg.constant_null_space();
      cg.preconditioner = mg.preconditioner();
      const VectorXd b = random_vector(n * n, 5);
      const dpgen::LinearSolveResult r = dpgen::solve_forward(mg.fine_operator(), b, cg);
      // The true residual, not only the recurrence's.
      VectorXd ax;
      mg.apply(r.solution, ax);
      CHECK((solvable(mg, b) - ax).norm() <= 1.01e-8 * solvable(mg, b).norm());
      mg_iterations.push_back(r.summary.iterations);
      MESSAGE(tc.name, " n = ", n, " MG-PCG iterations = ", r.summary.iterations);
      if (n == 128) { // the yardstick: Jacobi-preconditioned CG on the same problem
        dpgen::CgOptions jacobi = cg;
        jacobi.preconditioner = nullptr;
        jacobi.max_iterations = 5000;
        jacobi.jacobi_diagonal = dpgen::operator_diagonal(
            operator_for(tc.bc), smooth_coefficient(n), n, n, 1.0 / n, tc.bc);
        jacobi_iterations = dpgen::solve_forward(mg.fine_operator(), b, jacobi).summary.iterations;
      }
    }
    for (int it : mg_iterations)
      CHECK(it <= 20);
    CHECK(*std::max_element(mg_iterations.begin(), mg_iterations.end()) -
              *std::min_element(mg_iterations.begin(), mg_iterations.end()) <=
          3);
    CHECK(jacobi_iterations > 10 * mg_iterations[2]); // at 128x128
  }
}

TEST_CASE("implicit-solve gradients with the MG preconditioner match central differences") {
  // x = A(k)^-1 b on a 16x16 box with walls (Neumann, open Dirichlet top), L = |x - t|^2 / 2.
  // Forward and backward share one CgOptions, hence one Multigrid (A^T = A); the gradient w.r.t.
  // k comes from the generated adjoint of the operator kernel.
  for (const Case& tc : {kCases[3], kCases[0]}) {
    CAPTURE(tc.name);
    const int n = 16;
    const double h = 1.0 / n;
    const VectorXd k = smooth_coefficient(n) + 0.1 * random_vector(n * n, 6);
    const VectorXd b = random_vector(n * n, 7), target = random_vector(n * n, 8, -0.01, 0.01);
    const dpgen::LevelOperator op = operator_for(tc.bc);
    const auto solve = [&](const VectorXd& kk, const VectorXd& rhs) {
      dpgen::Multigrid mg(n, n, h, tc.bc, op, kk);
      dpgen::CgOptions cg;
      cg.relative_tolerance = 1e-13;
      cg.remove_null_space_mean = mg.constant_null_space();
      cg.preconditioner = mg.preconditioner();
      return dpgen::solve_forward(mg.fine_operator(), rhs, cg).solution;
    };
    const auto loss = [&](const VectorXd& x) { return 0.5 * (x - target).squaredNorm(); };

    dpgen::Multigrid mg(n, n, h, tc.bc, op, k);
    dpgen::CgOptions cg;
    cg.relative_tolerance = 1e-13;
    cg.remove_null_space_mean = mg.constant_null_space();
    int preconditioner_calls = 0;
    cg.preconditioner = [&](const VectorXd& r, VectorXd& z) {
      ++preconditioner_calls;
      mg.precondition(r, z);
    };
    const dpgen::LinearSolveResult forward = dpgen::solve_forward(mg.fine_operator(), b, cg);
    const VectorXd& x = forward.solution;
    const int forward_calls = preconditioner_calls;
    VectorXd b_bar, k_bar = VectorXd::Zero(n * n);
    const dpgen::LinearSolveResult backward = dpgen::implicit_solve_backward(
        mg.fine_operator(),
        [&](const VectorXd& xs, const VectorXd& lambda, VectorXd& g) {
          VectorXd x_adj = VectorXd::Zero(n * n);
          if (tc.bc.west == Boundary::periodic)
            neg_div_k_grad_periodic2d_adjoint(xs.data(), x_adj.data(), k.data(), g.data(),
                                              lambda.data(), n, n, h);
          else
            neg_div_k_grad_walls2d_adjoint(xs.data(), x_adj.data(), k.data(), g.data(),
                                           lambda.data(), n, n, h, wall(tc.bc.west),
                                           wall(tc.bc.east), wall(tc.bc.south), wall(tc.bc.north));
        },
        x, x - target, b_bar, k_bar, cg);
    // The backward solve ran preconditioned by the same V-cycle, in as few iterations.
    CHECK(preconditioner_calls - forward_calls >= backward.summary.iterations);
    CHECK(backward.summary.iterations <= 20);

    VectorXd fd_b(n * n), fd_k(n * n);
    VectorXd kk = k, bb = b;
    for (int c = 0; c < n * n; ++c) {
      // x is linear in b (exact differences up to the solve's rounding); smooth in k: a step of
      // 1e-5 leaves a truncation error of O(1e-10) relative.
      bb[c] = b[c] + 1e-3;
      const double up_b = loss(solve(k, bb));
      bb[c] = b[c] - 1e-3;
      fd_b[c] = (up_b - loss(solve(k, bb))) / 2e-3;
      bb[c] = b[c];
      kk[c] = k[c] + 1e-5;
      const double up_k = loss(solve(kk, b));
      kk[c] = k[c] - 1e-5;
      fd_k[c] = (up_k - loss(solve(kk, b))) / 2e-5;
      kk[c] = k[c];
    }
    CHECK((b_bar - fd_b).norm() <= 1e-6 * fd_b.norm());
    CHECK((k_bar - fd_k).norm() <= 1e-6 * fd_k.norm());
  }
}

TEST_CASE("sizes that are not powers of two: coarsened while even, or rejected clearly") {
  const Boundaries periodic = Boundaries::all(Boundary::periodic);
  // 96 = 3 * 32 halves down to 6x6 (36 cells); 48x80 to 6x10; 100 to 25x25 (625 cells);
  // 12x7 cannot be halved at all and is solved directly.
  for (auto [nx, ny] : {std::pair{96, 96}, {48, 80}, {100, 100}, {12, 7}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    VectorXd k = VectorXd::Ones(nx * ny);
    dpgen::Multigrid mg(nx, ny, 1.0 / nx, periodic, neg_div_k_grad_periodic2d, k);
    dpgen::CgOptions cg;
    cg.relative_tolerance = 1e-8;
    cg.remove_null_space_mean = true;
    cg.preconditioner = mg.preconditioner();
    const dpgen::LinearSolveResult r =
        dpgen::solve_forward(mg.fine_operator(), random_vector(nx * ny, 9), cg);
    CHECK(r.summary.iterations <= 20);
  }
  // 132 = 33 * 4: the coarsest grid would have 33x33 = 1089 cells.
  const VectorXd k = VectorXd::Ones(132 * 132);
  CHECK_THROWS_WITH_AS(
      dpgen::Multigrid(132, 132, 1.0 / 132, periodic, neg_div_k_grad_periodic2d, k),
      "multigrid: the 132x132 grid coarsens to 33x33 cells (3 levels), more than "
      "max_coarse_cells = 1024 for the direct coarse solve; use sides m * 2^L with small m "
      "(e.g. powers of two)",
      std::invalid_argument);
  dpgen::MultigridOptions five;
  five.levels = 5;
  CHECK_THROWS_WITH_AS(
      dpgen::Multigrid(24, 24, 1.0 / 24, periodic, neg_div_k_grad_periodic2d,
                       VectorXd::Ones(24 * 24), five),
      "multigrid: cannot build 5 levels from 24x24: level 3 has 3x3 cells and an odd side "
      "cannot be halved",
      std::invalid_argument);
}

TEST_CASE("non-convergence of MG-PCG is reported, never silent") {
  const int n = 64;
  const Boundaries bc = Boundaries::all(Boundary::dirichlet);
  dpgen::Multigrid mg(n, n, 1.0 / n, bc, operator_for(bc), smooth_coefficient(n));
  dpgen::CgOptions cg;
  cg.preconditioner = mg.preconditioner();
  cg.relative_tolerance = 1e-12;
  cg.max_iterations = 3;
  cg.name = "pressure";
  try {
    dpgen::solve_forward(mg.fine_operator(), random_vector(n * n, 10), cg);
    FAIL("expected a SolveError");
  } catch (const dpgen::SolveError& e) {
    CHECK(std::string(e.what()).rfind(
              "pressure forward (A x = b): did not converge after 3 iterations, residual ", 0) ==
          0);
    CHECK(e.summary().iterations == 3);
    CHECK(e.summary().final_residual_norm > e.summary().tolerance);
  }
  cg.throw_on_failure = false;
  const dpgen::LinearSolveResult r =
      dpgen::solve_forward(mg.fine_operator(), random_vector(n * n, 10), cg);
  CHECK(r.summary.termination == dpgen::CgTermination::max_iterations);
}

namespace {

bool same_bits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// One V-cycle z = B r and one operator application on `threads` threads.
void cycle_on(int threads, dpgen::Multigrid& mg, const VectorXd& r, VectorXd& z, VectorXd& ar) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  mg.precondition(r, z);
  mg.apply(r, ar);
  omp_set_num_threads(before);
}

} // namespace

TEST_CASE("row strips on 2 threads: the V-cycle and the operator give the 1-thread bits") {
  // 512x256: levels 512x256 .. 8x4; the finest (128K values) is split into row strips on 2
  // threads (the operator, both prolongation passes, the coefficient averages); the others
  // (below 64K values) run whole, though the check passes on the second.
  // Every boundary kind, so the periodic end strips (on copies) and the closed ones (in place)
  // both run.
  for (const Case& c : kCases) {
    CAPTURE(c.name);
    const int nx = 512, ny = 256;
    VectorXd k(nx * ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        k[j * nx + i] = 1.0 + 0.5 * std::sin(0.1 * i) * std::cos(0.13 * j);
    const int before = omp_get_max_threads();
    omp_set_num_threads(2); // setup by strips too (coefficient averages, probing)
    dpgen::Multigrid mg(nx, ny, 1.0 / ny, c.bc, operator_for(c.bc), k);
    omp_set_num_threads(before);
    CHECK(mg.parallel_rows(0));
    CHECK(mg.parallel_rows(1));
    CHECK_FALSE(mg.parallel_rows(mg.levels() - 1)); // 8x4: too small to split
    const VectorXd r = random_vector(nx * ny, 7);
    VectorXd z1, z2, a1, a2;
    cycle_on(1, mg, r, z1, a1);
    cycle_on(2, mg, r, z2, a2);
    CHECK(same_bits(a1, a2));
    CHECK(same_bits(z1, z2));
    // and the same as a hierarchy set up and run on one thread, which never splits
    dpgen::MultigridOptions whole;
    whole.parallel_rows = false;
    omp_set_num_threads(1);
    dpgen::Multigrid serial(nx, ny, 1.0 / ny, c.bc, operator_for(c.bc), k, whole);
    omp_set_num_threads(before);
    CHECK_FALSE(serial.parallel_rows(0));
    VectorXd z3, a3;
    cycle_on(1, serial, r, z3, a3);
    CHECK(same_bits(a1, a3));
    CHECK(same_bits(z1, z3));
  }
}

TEST_CASE("1, 2 or 3 sweeps: symmetric, contracting, and the 1-thread bits on 2 threads") {
  // The sweeps alternate between two vectors and the corrected iterate is placed so that the
  // last sweep writes the output: with an odd count it starts in the other vector. 512x256 on
  // 2 threads runs the finest level's sweeps and residual by row strips (each strip's update
  // made from its A x in the cache); one thread runs them whole.
  const int nx = 512, ny = 256;
  for (const Case& c : {kCases[0], kCases[3]}) {
    CAPTURE(c.name);
    VectorXd k(nx * ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        k[j * nx + i] = 1.0 + 0.5 * std::sin(0.1 * i) * std::cos(0.13 * j);
    double previous = 1.0;
    for (int sweeps = 1; sweeps <= 3; ++sweeps) {
      CAPTURE(sweeps);
      dpgen::MultigridOptions options;
      options.smoothing_sweeps = sweeps;
      const int before = omp_get_max_threads();
      omp_set_num_threads(2);
      dpgen::Multigrid mg(nx, ny, 1.0 / ny, c.bc, operator_for(c.bc), k, options);
      omp_set_num_threads(before);
      REQUIRE(mg.parallel_rows(0));
      const VectorXd r1 = solvable(mg, random_vector(nx * ny, 11));
      const VectorXd r2 = solvable(mg, random_vector(nx * ny, 12));
      VectorXd z1, z2, z1_two, a1, a2;
      cycle_on(1, mg, r1, z1, a1);
      cycle_on(1, mg, r2, z2, a2);
      CHECK(z1.dot(r2) == doctest::Approx(r1.dot(z2)).epsilon(1e-11));
      CHECK(z1.dot(r1) > 0.0);
      cycle_on(2, mg, r1, z1_two, a2);
      CHECK(same_bits(z1, z1_two));
      // from a nonzero guess (cycle): the same bits on 1 and 2 threads
      VectorXd x1 = r2, x2 = r2;
      omp_set_num_threads(1);
      mg.cycle(r1, x1);
      omp_set_num_threads(2);
      mg.cycle(r1, x2);
      omp_set_num_threads(before);
      CHECK(same_bits(x1, x2));
      // the stationary iteration x <- x + B (b - A x) from a nonzero guess, on 2 threads
      omp_set_num_threads(2);
      const double rate = contraction(mg, r1);
      omp_set_num_threads(before);
      MESSAGE(c.name, " sweeps = ", sweeps, " contraction = ", rate);
      CHECK(rate < (sweeps == 1 ? 0.5 : 0.35)); // 0.41, 0.30, 0.24 for both cases
      if (sweeps > 1)
        CHECK(rate < previous - 0.03); // more sweeps, a faster cycle
      previous = rate;
    }
  }
}

TEST_CASE("fused sweeps give the bits of sweep after sweep, on 1 and 2 threads") {
  // 1024x576 (590K cells): the finest level fuses its sweeps (strips of 64 rows: 9 of them, so
  // the 2 threads get 5 and 4); the next (147K cells) runs sweep after sweep. Every boundary
  // kind (the periodic end strips wrap rows of the other end in; closed ones stop at the walls)
  // with 1, 2 and 3 sweeps, from a zero guess (precondition) and from a nonzero one (cycle),
  // against the same hierarchy with fuse_sweeps off.
  const int nx = 1024, ny = 576;
  VectorXd k(nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      k[j * nx + i] = 1.0 + 0.5 * std::sin(0.1 * i) * std::cos(0.13 * j);
  const VectorXd r = random_vector(nx * ny, 21), guess = random_vector(nx * ny, 22);
  const int before = omp_get_max_threads();
  for (const Case& c : kCases)
    for (int sweeps = 1; sweeps <= 3; ++sweeps) {
      if (sweeps != 2 && c.bc.west != Boundary::periodic && c.bc.north != Boundary::dirichlet)
        continue; // 1 and 3 sweeps on the periodic and the mixed case only
      CAPTURE(c.name);
      CAPTURE(sweeps);
      dpgen::MultigridOptions fused, plain;
      fused.smoothing_sweeps = plain.smoothing_sweeps = sweeps;
      plain.fuse_sweeps = false;
      dpgen::Multigrid a(nx, ny, 1.0 / ny, c.bc, operator_for(c.bc), k, fused);
      dpgen::Multigrid b(nx, ny, 1.0 / ny, c.bc, operator_for(c.bc), k, plain);
      CHECK(a.fuses_sweeps(0));
      CHECK_FALSE(a.fuses_sweeps(1)); // 147K cells stay in the cache from sweep to sweep
      CHECK_FALSE(b.fuses_sweeps(0));
      for (int threads = 1; threads <= 2; ++threads) {
        CAPTURE(threads);
        omp_set_num_threads(threads);
        VectorXd za, zb, xa = guess, xb = guess;
        a.precondition(r, za);
        b.precondition(r, zb);
        a.cycle(r, xa);
        b.cycle(r, xb);
        omp_set_num_threads(before);
        CHECK(same_bits(za, zb));
        CHECK(same_bits(xa, xb));
        CHECK(za.allFinite());
      }
    }
}

TEST_CASE("an operator that is not row-local runs whole, and stays right") {
  // Row j of this operator also depends on the grid's height (a shift that grows with ny):
  // strips would see other heights, so the setup check must keep it whole on every level.
  const int n = 128;
  const dpgen::Boundaries bc = Boundaries::all(Boundary::periodic);
  const dpgen::LevelOperator shifted = [](const double* x, const double* k, double* y, int nx,
                                          int ny, double h) {
    neg_div_k_grad_periodic2d(x, k, y, nx, ny, h);
    for (int c = 0; c < nx * ny; ++c)
      y[c] += 1e-3 * ny * x[c];
  };
  dpgen::Multigrid mg(n, n, 1.0 / n, bc, shifted, smooth_coefficient(n));
  for (int l = 0; l < mg.levels(); ++l)
    CHECK_FALSE(mg.parallel_rows(l));
  const VectorXd x = random_vector(n * n, 3);
  VectorXd y, expected(n * n);
  mg.apply(x, y);
  shifted(x.data(), smooth_coefficient(n).data(), expected.data(), n, n, 1.0 / n);
  CHECK(same_bits(y, expected));
}

TEST_CASE("bad operators and inputs are rejected with a clear message") {
  const int n = 16;
  const Boundaries periodic = Boundaries::all(Boundary::periodic);
  const VectorXd k = VectorXd::Ones(n * n);
  // A Laplacian with the wrong sign: negative diagonal.
  const dpgen::LevelOperator negated = [](const double* x, const double* kk, double* y, int nx,
                                          int ny, double h) {
    neg_div_k_grad_periodic2d(x, kk, y, nx, ny, h);
    for (int c = 0; c < nx * ny; ++c)
      y[c] = -y[c];
  };
  CHECK_THROWS_WITH_AS(dpgen::Multigrid(n, n, 1.0 / n, periodic, negated, k),
                       doctest::Contains("multigrid: the operator's diagonal is -1.02e+03 at cell "
                                         "(0, 0) of level 0 (16x16); Jacobi smoothing needs a "
                                         "positive diagonal"),
                       std::invalid_argument);
  // A non-symmetric operator (an upwind advection term added): CG and this V-cycle do not
  // apply; the normal equations of implicit_solve.hpp do (without this preconditioner).
  const dpgen::LevelOperator advective = [](const double* x, const double* kk, double* y, int nx,
                                            int ny, double h) {
    neg_div_k_grad_periodic2d(x, kk, y, nx, ny, h);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        y[j * nx + i] += 3.0 * (x[j * nx + i] - x[j * nx + (i + nx - 1) % nx]) / h;
  };
  CHECK_THROWS_WITH_AS(dpgen::Multigrid(n, n, 1.0 / n, periodic, advective, k),
                       doctest::Contains("multigrid: the operator is not symmetric on the "
                                         "coarsest level (8x8)"),
                       std::invalid_argument);
  VectorXd bad_k = k;
  bad_k[5] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(dpgen::Multigrid(n, n, 1.0 / n, periodic, neg_div_k_grad_periodic2d, bad_k),
                       "multigrid: coefficient k contains nan at index 5", std::invalid_argument);
  CHECK_THROWS_WITH_AS(
      dpgen::Multigrid(n, n, 1.0 / n, periodic, neg_div_k_grad_periodic2d, VectorXd::Ones(7)),
      "multigrid: coefficient k has size 7, expected 256", std::invalid_argument);
  CHECK_THROWS_WITH_AS(
      dpgen::Multigrid(
          n, n, 1.0 / n,
          {Boundary::periodic, Boundary::neumann, Boundary::periodic, Boundary::periodic},
          neg_div_k_grad_periodic2d, k),
      "multigrid: periodic must be set on both sides of an axis (west periodic, east neumann, "
      "south periodic, north periodic)",
      std::invalid_argument);
  dpgen::MultigridOptions heavy;
  heavy.jacobi_weight = 1.5;
  CHECK_THROWS_WITH_AS(
      dpgen::Multigrid(n, n, 1.0 / n, periodic, neg_div_k_grad_periodic2d, k, heavy),
      "multigrid: jacobi_weight must lie in (0, 1] (got 1.5)", std::invalid_argument);
  dpgen::Multigrid mg(n, n, 1.0 / n, periodic, neg_div_k_grad_periodic2d, k);
  VectorXd z;
  CHECK_THROWS_WITH_AS(mg.precondition(VectorXd::Ones(9), z),
                       "multigrid: residual has size 9, expected 256", std::invalid_argument);
}
