// pressure_optimization (examples/pressure_optimization.cpp) on a 2D block decomposition: the
// divergence, Poisson operator and gradient are the generated halo kernels on each rank's block;
// the Poisson solve is PETSc's CG on a MatShell of the halo kernel (preconditioned by BoomerAMG
// when PETSc has hypre), and its gradient the implicit rule: one more solve, with the same
// operator (it is symmetric). Loss and norms are summed over ranks; the left-half velocities are
// updated block by block. The same loss history as the single-process example, to the solver
// tolerance.
//
//   mpirun -np 4 build/examples/mpi/pressure_optimization_mpi --csv out/p4.csv
#include "common/cli.hpp"
#include "mpi/mpi_common.hpp"

#include "dpgen/mpi/decomposition.hpp"
#include "dpgen/mpi/halo.hpp"
#include "dpgen/petsc/linear_solver.hpp"
#include "halo_kernels.hpp"
#include "mac_divergence_halo_adjoint.hpp"
#include "mac_subtract_gradient_halo_adjoint.hpp"
#include "neg_laplacian_halo2d_adjoint.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using dpgen::mpi::Decomposition;
using dpgen::mpi::exchange_halos;
using dpgen::mpi::exchange_halos_adjoint;
using Eigen::VectorXd;

// The projection P(u, v) = (u, v) - grad p with -laplace p = -div(u, v), on the blocks. Every
// vector in and out is an interior vector of the decomposition.
struct Projection {
  const Decomposition& dec;
  double h;
  dpgen::petsc::LinearSolver solver;
  VectorXd pressure, lambda; // last solutions: warm starts, and p for the backward pass
  VectorXd up, vp, pp;       // padded inputs of the last forward pass, halos exchanged
  dpgen::petsc::SolveSummary forward_summary, backward_summary;

  Projection(const Decomposition& d, double h_, dpgen::petsc::SolverOptions options)
      : dec(d), h(h_),
        solver(
            d,
            [this](const VectorXd& x, VectorXd& y) {
              neg_laplacian_halo2d(x.data(), y.data(), dec.local(0), dec.local(1), h);
            },
            std::move(options)) {}

  void forward(const VectorXd& u, const VectorXd& v, VectorXd& u_out, VectorXd& v_out) {
    const int nx = dec.local(0), ny = dec.local(1);
    up = dec.pad(u), vp = dec.pad(v);
    exchange_halos(dec, up);
    exchange_halos(dec, vp);
    VectorXd div = VectorXd::Zero(dec.padded_size());
    mac_divergence_halo(up.data(), vp.data(), div.data(), nx, ny, h);
    const VectorXd b = -dec.interior(div); // -laplace p = -div u
    forward_summary = solver.solve(b, pressure, pressure.size() > 0 ? &pressure : nullptr);
    pp = dec.pad(pressure);
    exchange_halos(dec, pp);
    VectorXd uo = VectorXd::Zero(dec.padded_size()), vo = uo;
    mac_subtract_gradient_halo(up.data(), vp.data(), pp.data(), uo.data(), vo.data(), nx, ny, h);
    u_out = dec.interior(uo), v_out = dec.interior(vo);
  }

  // Given the adjoints of the projected field, the adjoints of (u, v) (overwritten).
  void backward(const VectorXd& u_out_adj, const VectorXd& v_out_adj, VectorXd& u_adj,
                VectorXd& v_adj) {
    const int nx = dec.local(0), ny = dec.local(1);
    VectorXd ua = VectorXd::Zero(dec.padded_size()), va = ua, pa = ua;
    const VectorXd uo_seed = dec.pad(u_out_adj), vo_seed = dec.pad(v_out_adj);
    // (u, v, p) -> (u - dp/dx, v - dp/dy): generated adjoint; p is read in the west and south
    // halos, so its adjoint goes back to the owners before the solve.
    mac_subtract_gradient_halo_adjoint(up.data(), ua.data(), vp.data(), va.data(), pp.data(),
                                       pa.data(), uo_seed.data(), vo_seed.data(), nx, ny, h);
    exchange_halos_adjoint(dec, pa);
    // p = A^-1 b: b_adj = A^-T p_adj, one more solve (A symmetric: the same solve)
    backward_summary =
        solver.solve_transpose(dec.interior(pa), lambda, lambda.size() > 0 ? &lambda : nullptr);
    // b = -div(u, v): div_adj = -b_adj, then the generated divergence adjoint
    const VectorXd div_seed = dec.pad(-lambda);
    mac_divergence_halo_adjoint(up.data(), ua.data(), vp.data(), va.data(), div_seed.data(), nx, ny,
                                h);
    exchange_halos_adjoint(dec, ua); // u and v were read in the east and north halos
    exchange_halos_adjoint(dec, va);
    u_adj = dec.interior(ua), v_adj = dec.interior(va);
  }
};

int run(int argc, char** argv) {
  dpgen_examples::Args args(argc, argv, "pressure_optimization_mpi",
                            "pressure_optimization on a 2D block decomposition (MPI, dpgen halo "
                            "kernels, PETSc solves).");
  const int nx = args.get_int("--nx", 32, "cells in x (periodic)");
  const int ny = args.get_int("--ny", 32, "cells in y (periodic)");
  const int iters = args.get_int("--iters", 60, "optimizer iterations");
  const std::string method = args.get_string("--optimizer", "gd", "gd or adam");
  const double lr = args.get_double("--lr", 0.4, "learning rate");
  const double tol = args.get_double("--cg-tol", 1e-10, "relative CG tolerance, both solves");
  const std::string pc =
      args.get_string("--pc", "automatic",
                      "preconditioner: automatic (BoomerAMG if PETSc has hypre, else GAMG), "
                      "boomeramg, gamg, jacobi or none");
  const std::string csv =
      args.get_string("--csv", "", "CSV log path (iter,loss,grad_norm,seconds)");
  const double require = args.get_double("--require-reduction", 0,
                                         "exit with an error unless the loss drops by this factor");
  const bool quiet = args.get_int("--quiet", 0, "1: no progress lines") != 0;
  if (args.finish())
    return 0;
  if (nx < 4 || ny < 4 || nx % 2 || iters < 0)
    throw std::invalid_argument("need even --nx >= 4, --ny >= 4, --iters >= 0");

  dpgen::petsc::Session petsc;
  const Decomposition dec(MPI_COMM_WORLD, {{nx, ny}, {true, true}, {}, 1});
  const double h = 1.0 / nx;
  dpgen::petsc::SolverOptions options;
  options.name = "pressure solve";
  options.relative_tolerance = tol;
  options.absolute_tolerance = 1e-14;
  options.max_iterations = 20 * nx * ny;
  options.preconditioner = dpgen::petsc::parse_preconditioner(pc);
  options.constant_null_space = true; // periodic Poisson: constants are its null space
  Projection proj(dec, h, options);

  // Cells of this block, with their global position; the left half is optimized.
  const Eigen::Index n = dec.interior_size();
  std::vector<int> gi(n), gj(n), left;
  dec.for_each_row([&](Eigen::Index flat, Eigen::Index, int j, int) {
    for (int i = 0; i < dec.local(0); ++i) {
      gi[flat + i] = dec.offset(0) + i, gj[flat + i] = dec.offset(1) + j;
      if (gi[flat + i] < nx / 2)
        left.push_back(static_cast<int>(flat + i));
    }
  });

  // The target: the projection of a jet in the left half (the single-process example's field).
  VectorXd u_star = VectorXd::Zero(n), v_star = VectorXd::Zero(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double x = (gi[k] + 0.5) / nx, y = (gj[k] + 0.5) / ny;
    if (gi[k] >= nx / 2)
      continue;
    const double bump = std::exp(-(std::pow((x - 0.4) / 0.06, 2) + std::pow((y - 0.5) / 0.2, 2)));
    v_star[k] = bump;
    u_star[k] = 0.5 * bump * std::sin(6.283185307179586 * y);
  }
  VectorXd u_target, v_target;
  proj.forward(u_star, v_star, u_target, v_target);

  const int m = static_cast<int>(left.size());
  auto unpack = [&](const VectorXd& x, VectorXd& u, VectorXd& v) {
    u = VectorXd::Zero(n), v = VectorXd::Zero(n);
    for (int q = 0; q < m; ++q)
      u[left[q]] = x[q], v[left[q]] = x[m + q];
  };
  // L = sum over the right half of all blocks of |P(u, v) - target|^2.
  auto loss_and_gradient = [&](const VectorXd& x, VectorXd& grad) {
    VectorXd u, v, u_proj, v_proj;
    unpack(x, u, v);
    proj.forward(u, v, u_proj, v_proj);
    VectorXd u_out_adj = VectorXd::Zero(n), v_out_adj = VectorXd::Zero(n);
    double loss = 0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (gi[k] < nx / 2)
        continue;
      const double du = u_proj[k] - u_target[k], dv = v_proj[k] - v_target[k];
      loss += du * du + dv * dv;
      u_out_adj[k] = 2 * du, v_out_adj[k] = 2 * dv;
    }
    VectorXd u_adj, v_adj;
    proj.backward(u_out_adj, v_out_adj, u_adj, v_adj);
    grad.resize(2 * m);
    for (int q = 0; q < m; ++q)
      grad[q] = u_adj[left[q]], grad[m + q] = v_adj[left[q]];
    return dec.sum(loss); // MPI_Allreduce
  };

  auto optimizer =
      dpgen_examples::make_distributed_optimizer(method, lr, "pressure_optimization_mpi");
  dpgen_examples::LossCurve curve;
  dpgen::TrainOptions train =
      dpgen_examples::distributed_train_options(iters, csv, curve, dec, quiet);
  VectorXd x = VectorXd::Zero(2 * m);
  MPI_Barrier(dec.comm());
  const auto start = std::chrono::steady_clock::now();
  const dpgen::TrainSummary s = dpgen::train(loss_and_gradient, *optimizer, x, train);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double slowest = dpgen_examples::max_over_ranks(dec, seconds);
  const double reduction = s.initial_loss / s.final_loss;
  if (dec.rank() == 0) {
    std::printf("loss %.6e -> %.6e (%.0fx lower) in %d iterations; %s\n", s.initial_loss,
                s.final_loss, reduction, s.iterations, s.message.c_str());
    std::printf("last solves: %s; %s\n", proj.forward_summary.message.c_str(),
                proj.backward_summary.message.c_str());
    std::printf("ranks %d (%dx%d blocks), grid %dx%d: %.3f ms per gradient (slowest rank, %d "
                "gradients)\n",
                dec.size(), dec.processes(0), dec.processes(1), nx, ny,
                1e3 * slowest / s.evaluations, s.evaluations);
  }
  return dec.rank() == 0 ? dpgen_examples::check_reduction(reduction, require) : 0;
}

} // namespace

int main(int argc, char** argv) {
  dpgen_examples::MpiScope mpi(&argc, &argv);
  return dpgen_examples::run_distributed("pressure_optimization_mpi",
                                         [&] { return run(argc, argv); });
}
