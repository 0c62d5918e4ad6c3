// last_writer (tests/styles/): stores the write-once rule allows once it
// follows the iterations (issue 20): a store in one iteration only (`if (i ==
// 0) out[0] = ...` inside the loop over i), and two stores of one loop that
// meet across iterations, where the later writer wins (`K[j] = ...; K[j + 1]
// = ...;`, as a tridiagonal setup or a staggered-edge loop writes them).
#include "dpgen/annotate.hpp"

#include <cmath>

// The first iteration also stores a diagnostic; the last one the closing face.
DPGEN_KERNEL void lw_first_last(DPGEN_IN const double* a, DPGEN_OUT double* b,
                                DPGEN_OUT double* ends, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = 2.0 * a[i] * a[i];
    if (i == 0)
      ends[0] = std::sin(a[i]);
    if (i == n - 1)
      ends[1] = a[i] * a[0];
  }
}

// Each iteration sets its diagonal entry and a guess for the next one; the
// next iteration overwrites the guess, so only the last guess stays.
DPGEN_KERNEL void lw_next_guess(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = 0.5 * a[j];
  }
}

// The same the other way round (C89): the guess first, then the entry; a
// stride of 2 (edges at even indices, cells at odd ones).
DPGEN_KERNEL void lw_stride2_c89(DPGEN_IN const double* u, DPGEN_OUT double* e, int n) {
  int j;
  for (j = 0; j < n; j++) {
    e[2 * j + 2] = u[j];
    e[2 * j] = std::exp(u[j]);
    e[2 * j + 1] = u[j] * u[j];
  }
}
