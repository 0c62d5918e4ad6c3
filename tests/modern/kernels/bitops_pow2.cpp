// corpus: form=bitops expect=accept
// Power-of-two grids: periodic neighbours by masking ((i + 1) & (n - 1)), the
// flat index (j << lg) | i; and Haar pairs, whose partner is i ^ 1.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void periodic_laplace_pow2(DPGEN_IN const double* u, DPGEN_OUT double* lap, int lg) {
  const int n = 1 << lg, mask = n - 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int ip = (i + 1) & mask, im = (i - 1) & mask;
      const int jp = (j + 1) & mask, jm = (j - 1) & mask;
      lap[(j << lg) | i] = u[(j << lg) | ip] + u[(j << lg) | im] + u[(jp << lg) | i] +
                           u[(jm << lg) | i] - 4.0 * u[(j << lg) | i];
    }
}

DPGEN_KERNEL void haar_pairs(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const int m = n >> 1;
  for (int i = 0; i < 2 * m; ++i) {
    const double avg = 0.5 * (u[i] + u[i ^ 1]);
    out[i] = (i & 1) ? u[i] - avg : avg;
  }
}
