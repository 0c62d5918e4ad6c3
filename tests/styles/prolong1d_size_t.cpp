// Multigrid linear-interpolation prolongation, vertex-centred 1D: injection
// at even fine points, averages at odd ones; two loops with size_t counters.
#include "dpgen/annotate.hpp"

#include <cstddef>

DPGEN_KERNEL void prolong1d_size_t(DPGEN_IN const double* coarse, DPGEN_OUT double* fine,
                                   std::size_t nc) {
  for (std::size_t I = 0; I < nc; ++I)
    fine[2 * I] = coarse[I];
  for (std::size_t I = 0; I + 1 < nc; ++I)
    fine[2 * I + 1] = 0.5 * (coarse[I] + coarse[I + 1]);
}
