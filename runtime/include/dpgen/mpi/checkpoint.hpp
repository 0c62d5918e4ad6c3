// Gradients through unrolled time loops on a block decomposition: every rank runs
// dpgen::unrolled_gradient on its own block (its own tape or Revolve snapshots), in lockstep.
#pragma once

#include "dpgen/checkpoint.hpp"
#include "dpgen/mpi/decomposition.hpp"

#include <mpi.h>

#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dpgen::mpi {

/// dpgen::unrolled_gradient on every rank's block, with the loss summed over the ranks.
///
/// The callables are those of dpgen::unrolled_gradient acting on this rank's interior vectors;
/// `step` and `step_adjoint` typically exchange halos (forward) and run the reverse exchange
/// (backward), which are collective. The schedule (which step runs when, which state is stored
/// or recomputed) depends only on `steps` and the options, so ranks that agree on them make the
/// same calls in the same order and their exchanges pair up; this function checks that they
/// agree, and throws on every rank, naming the disagreeing ranks, when they do not (instead of
/// leaving them waiting for each other). Each rank stores only its own block's states: with
/// Revolve, `snapshots` states of its block. `loss_adjoint` returns this block's loss terms;
/// the result's loss is their sum over the ranks (state_adjoint and final_state stay per block).
template <typename Step, typename StepAdjoint, typename LossAdjoint>
UnrolledGradient unrolled_gradient(const Decomposition& dec, const Eigen::VectorXd& initial_state,
                                   int steps, Step&& step, StepAdjoint&& step_adjoint,
                                   LossAdjoint&& loss_adjoint,
                                   const CheckpointOptions& options = {}) {
  const std::array<int, 3> mine{steps, static_cast<int>(options.strategy), options.snapshots};
  std::vector<int> all(3 * static_cast<std::size_t>(dec.size()));
  MPI_Allgather(mine.data(), 3, MPI_INT, all.data(), 3, MPI_INT, dec.comm());
  const auto schedule = [&](int r) {
    const int* s = &all[3 * static_cast<std::size_t>(r)];
    return detail::message(s[0], " steps, ",
                           s[1] == static_cast<int>(CheckpointStrategy::revolve)
                               ? detail::message("Revolve with ", s[2], " snapshots")
                               : std::string("full tape"));
  };
  for (int r = 1; r < dec.size(); ++r)
    if (all[3 * r] != all[0] || all[3 * r + 1] != all[1] ||
        (all[1] == static_cast<int>(CheckpointStrategy::revolve) && all[3 * r + 2] != all[2]))
      throw std::invalid_argument(detail::message(
          dec.where(), ": checkpoint: the ranks disagree on the time loop: rank 0 has ",
          schedule(0), ", rank ", r, " has ", schedule(r)));
  UnrolledGradient result = dpgen::unrolled_gradient(
      initial_state, steps, std::forward<Step>(step), std::forward<StepAdjoint>(step_adjoint),
      std::forward<LossAdjoint>(loss_adjoint), options);
  result.loss = dec.sum(result.loss);
  return result;
}

} // namespace dpgen::mpi
