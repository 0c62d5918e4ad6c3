// advection_inverse (examples/advection_inverse.cpp) on a 1D block decomposition: every rank
// owns a block of the periodic grid, runs the generated upwind_step_halo kernel on it after a
// halo exchange, and the generated adjoint plus the reverse exchange backwards; states are stored
// or recomputed (Revolve) per rank (dpgen/mpi/checkpoint.hpp). The loss is summed over ranks
// (MPI_Allreduce), the velocity is updated block by block. The same loss history as the
// single-process example, to round-off.
//
//   mpirun -np 4 build/examples/mpi/advection_inverse_mpi --csv out/adv4.csv
#include "common/cli.hpp"
#include "mpi/mpi_common.hpp"

#include "dpgen/mpi/checkpoint.hpp"
#include "dpgen/mpi/decomposition.hpp"
#include "dpgen/mpi/halo.hpp"
#include "halo_kernels.hpp"
#include "upwind_step_halo_adjoint.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace {

using dpgen::mpi::Decomposition;
using Eigen::VectorXd;

constexpr double kPi = 3.14159265358979323846;

// One upwind step on the blocks, as a map of interior vectors, and its adjoint:
//   next = K(E P d)  and  d_adj += P^T E^T K^T next_adj,
// P: interior -> padded, E: halo exchange, K: the halo kernel (u fixed, its halos exchanged).
struct BlockStep {
  const Decomposition& dec;
  double dt, dx;
  VectorXd u;                   // padded velocity, halos exchanged
  VectorXd u_adj;               // padded adjoint of u, reverse-exchanged once at the end
  VectorXd d, out, seed, d_adj; // padded work arrays (the halos of out and seed stay 0)

  BlockStep(const Decomposition& dec_, double dt_, double dx_)
      : dec(dec_), dt(dt_), dx(dx_), d(VectorXd::Zero(dec_.padded_size())),
        out(VectorXd::Zero(dec_.padded_size())), seed(VectorXd::Zero(dec_.padded_size())),
        d_adj(dec_.padded_size()) {}

  void set_velocity(const VectorXd& u_interior) {
    u = dec.pad(u_interior);
    dpgen::mpi::exchange_halos(dec, u);
    u_adj = VectorXd::Zero(dec.padded_size());
  }
  void forward(const VectorXd& d_in, VectorXd& next) {
    dec.copy_interior(d_in, d);
    dpgen::mpi::exchange_halos(dec, d);
    upwind_step_halo(d.data(), u.data(), out.data(), dec.local(0), dt, dx);
    dec.extract_interior(out, next);
  }
  void adjoint(const VectorXd& d_in, const VectorXd& next_adj, VectorXd& d_in_adj) {
    dec.copy_interior(d_in, d);
    dpgen::mpi::exchange_halos(dec, d);
    dec.copy_interior(next_adj, seed);
    d_adj.setZero();
    upwind_step_halo_adjoint(d.data(), d_adj.data(), u.data(), u_adj.data(), seed.data(),
                             dec.local(0), dt, dx);
    dpgen::mpi::exchange_halos_adjoint(dec, d_adj); // halo adjoints back to their owners
    dec.extract_interior(d_adj, d_in_adj, /*add=*/true);
  }
  // dL/du on this block: u's halo adjoints (reads of u in the halos) back to their owners.
  VectorXd velocity_gradient() {
    dpgen::mpi::exchange_halos_adjoint(dec, u_adj);
    return dec.interior(u_adj);
  }
};

int run(int argc, char** argv) {
  dpgen_examples::Args args(
      argc, argv, "advection_inverse_mpi",
      "advection_inverse on a block decomposition (MPI, dpgen halo kernels).");
  const int cells = args.get_int("--cells", 128, "grid cells on [0, 1), periodic");
  const int steps = args.get_int("--steps", 100, "upwind steps T");
  const int iters = args.get_int("--iters", 300, "optimizer iterations");
  const std::string method = args.get_string("--optimizer", "gd", "gd or adam");
  const double lr = args.get_double("--lr", 0.01, "learning rate");
  const int checkpoints =
      args.get_int("--checkpoints", 0, "0: store every state; K > 0: Revolve with K snapshots");
  const std::string csv =
      args.get_string("--csv", "", "CSV log path (iter,loss,grad_norm,seconds)");
  const double require = args.get_double("--require-reduction", 0,
                                         "exit with an error unless the loss drops by this factor");
  const bool quiet = args.get_int("--quiet", 0, "1: no progress lines") != 0;
  if (args.finish())
    return 0;
  if (cells < 3 || steps < 1 || iters < 0 || checkpoints < 0)
    throw std::invalid_argument("need --cells >= 3, --steps >= 1, --iters >= 0, "
                                "--checkpoints >= 0");

  const Decomposition dec(MPI_COMM_WORLD, {{cells}, {true}, {}, 1});
  const int n = dec.local(0);
  const double dx = 1.0 / cells, dt = 0.5 * dx;

  // d0 and u_true at this block's cell centres (the single-process example's formulas); the
  // target is d0 advected by u_true with the same distributed step: the same bits as on one
  // process, since every cell does the same arithmetic on the same values.
  VectorXd d0(n), u_true(n);
  for (int i = 0; i < n; ++i) {
    const double x = (dec.offset(0) + i + 0.5) * dx;
    const double r = (x - 0.3) / 0.15;
    d0[i] = std::abs(r) < 1 ? std::pow(std::cos(0.5 * kPi * r), 2) : 0.0;
    u_true[i] = 0.2 + 0.1 * std::sin(2 * kPi * x);
  }
  BlockStep step(dec, dt, dx);
  step.set_velocity(u_true);
  VectorXd target = d0, next(n);
  for (int t = 0; t < steps; ++t) {
    step.forward(target, next);
    target.swap(next);
  }

  dpgen::CheckpointOptions cp;
  if (checkpoints > 0)
    cp = {dpgen::CheckpointStrategy::revolve, checkpoints};
  dpgen::CheckpointStats stats;
  // L(u) = sum over all ranks of |d(T) - target|^2, and this block of dL/du.
  auto loss_and_gradient = [&](const VectorXd& u, VectorXd& grad) {
    step.set_velocity(u);
    const dpgen::UnrolledGradient g = dpgen::mpi::unrolled_gradient(
        dec, d0, steps, [&](int, const VectorXd& d, VectorXd& nx) { step.forward(d, nx); },
        [&](int, const VectorXd& d, const VectorXd& na, VectorXd& da) { step.adjoint(d, na, da); },
        [&](int t, const VectorXd& d, VectorXd& d_adj) {
          if (t != steps)
            return 0.0;
          const VectorXd r = d - target;
          d_adj += 2.0 * r;
          return r.squaredNorm(); // this block's part
        },
        cp);
    grad = step.velocity_gradient();
    stats = g.stats;
    return g.loss; // summed over the ranks (MPI_Allreduce)
  };

  VectorXd u = VectorXd::Constant(n, 0.1); // first guess
  auto optimizer = dpgen_examples::make_distributed_optimizer(method, lr, "advection_inverse_mpi");
  dpgen_examples::LossCurve curve;
  dpgen::TrainOptions options =
      dpgen_examples::distributed_train_options(iters, csv, curve, dec, quiet);
  MPI_Barrier(dec.comm());
  const auto start = std::chrono::steady_clock::now();
  const dpgen::TrainSummary s = dpgen::train(loss_and_gradient, *optimizer, u, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double slowest = dpgen_examples::max_over_ranks(dec, seconds);
  const double reduction = s.initial_loss / s.final_loss;
  if (dec.rank() == 0) {
    std::printf("loss %.6e -> %.6e (%.0fx lower) in %d iterations; %s\n", s.initial_loss,
                s.final_loss, reduction, s.iterations, s.message.c_str());
    std::printf("ranks %d, cells %d (%d on rank 0), %d steps: %.3f ms per gradient "
                "(slowest rank, %d gradients); per rank per gradient: %lld forward steps, %d "
                "states stored\n",
                dec.size(), cells, n, steps, 1e3 * slowest / s.evaluations, s.evaluations,
                stats.forward_steps, stats.max_snapshots);
  }
  return dec.rank() == 0 ? dpgen_examples::check_reduction(reduction, require) : 0;
}

} // namespace

int main(int argc, char** argv) {
  dpgen_examples::MpiScope mpi(&argc, &argv);
  return dpgen_examples::run_distributed("advection_inverse_mpi", [&] { return run(argc, argv); });
}
