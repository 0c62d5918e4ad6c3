// What the distributed examples share: MPI around main(), rank 0 alone printing and logging,
// gradient norms reduced over the ranks, and errors reported with the rank before MPI_Abort.
#pragma once

#include "common/report.hpp"

#include "dpgen/mpi/decomposition.hpp"
#include "dpgen/optim.hpp"
#include "dpgen/train.hpp"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

namespace dpgen_examples {

/// MPI_Init / MPI_Finalize around a scope.
class MpiScope {
public:
  MpiScope(int* argc, char*** argv) { MPI_Init(argc, argv); }
  MpiScope(const MpiScope&) = delete;
  MpiScope& operator=(const MpiScope&) = delete;
  ~MpiScope() { MPI_Finalize(); }
};

inline int world_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

/// Runs body() and returns its status; an exception is printed with the rank that threw it and
/// ends every rank (MPI_Abort), since the others may be waiting in a collective.
template <typename Body> int run_distributed(const char* program, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const std::string what = e.what();
    // messages of dpgen::mpi already start with "rank R of N"
    if (what.rfind("rank ", 0) == 0)
      std::fprintf(stderr, "%s: error: %s\n", program, what.c_str());
    else
      std::fprintf(stderr, "%s: error: rank %d of %d: %s\n", program, rank, size, what.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
}

/// The largest value of x over the decomposition's ranks (e.g. the slowest rank's time).
inline double max_over_ranks(const dpgen::mpi::Decomposition& dec, double x) {
  double m = 0;
  MPI_Allreduce(&x, &m, 1, MPI_DOUBLE, MPI_MAX, dec.comm());
  return m;
}

/// The optimizers whose updates act on each parameter alone (gd, adam), so that every rank
/// updates its own block; L-BFGS needs global dot products inside LBFGS++ and is refused.
inline std::unique_ptr<dpgen::Optimizer>
make_distributed_optimizer(const std::string& name, double lr, const std::string& program) {
  if (name == "lbfgs")
    throw std::invalid_argument(program + ": --optimizer lbfgs is not available distributed "
                                          "(its dot products would be per rank); use gd or adam");
  return make_optimizer(name, lr, program);
}

/// train_options for a distributed run: the gradient norm reduced over the ranks; progress
/// lines and the loss curve (unless `quiet`) and the CSV log on rank 0 only.
inline dpgen::TrainOptions distributed_train_options(int iters, const std::string& csv,
                                                     LossCurve& curve,
                                                     const dpgen::mpi::Decomposition& dec,
                                                     bool quiet = false) {
  const bool root = dec.rank() == 0;
  dpgen::TrainOptions opts = train_options(iters, root ? csv : "", curve, root && !quiet);
  opts.norm = [&dec](const Eigen::VectorXd& g) { return dec.norm(g); };
  return opts;
}

} // namespace dpgen_examples
