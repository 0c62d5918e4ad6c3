// corpus: form=return expect=accept
// A kernel that returns a value: the checksum a solver prints each step.
// Adjoint: checksum_adjoint(u, u_adj, n, double checksum_return_adj) -> void.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL double checksum(DPGEN_IN const double* u, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i)
    s += u[i] * u[i];
  return s;
}
