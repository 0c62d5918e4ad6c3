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

// The pair over a shorter loop after a guard; in a loop counting down, where
// the later iteration is the smaller j (iteration j - 1 writes L[j] after
// iteration j did, so L[j] = a[j-1]^2 for j >= 1 and L[0] = exp(a[0]), L[n]
// = a[n-1]^2); a store pinned by an equation that is not affine (`i == n / 2`).
DPGEN_KERNEL void lw_guarded_down(DPGEN_IN const double* a, DPGEN_OUT double* K,
                                  DPGEN_OUT double* L, DPGEN_OUT double* mid, int n) {
  if (n < 2)
    return;
  for (int j = 0; j < n - 1; j++) {
    K[j] = a[j] * a[j + 1];
    K[j + 1] = a[j + 1] - a[j];
  }
  for (int j = n - 1; j >= 0; --j) {
    L[j] = std::exp(a[j]);
    L[j + 1] = a[j] * a[j];
  }
  for (int i = 0; i < n; ++i)
    if (i == n / 2)
      mid[0] = a[i] * a[i];
}
