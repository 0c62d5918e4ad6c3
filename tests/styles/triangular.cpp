// Triangular loop nests the way linear-algebra and pairwise codes write them
// (issue 20): an inner bound that moves with the outer counter.
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

// y = L x for the lower triangle of a dense row-major L, with a running sum.
DPGEN_KERNEL void tri_lower_matvec(DPGEN_IN const double* L, DPGEN_IN const double* x,
                                   DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i; ++j)
      s += L[i * n + j] * x[j];
    y[i] = s;
  }
}

// Pairwise interactions over j > i, each pair written once (strict upper
// triangle), C89 counters.
DPGEN_KERNEL void tri_pairs_upper(DPGEN_IN const double* q, DPGEN_OUT double* e, int n) {
  int i, j;
  for (i = 0; i < n; i++)
    for (j = i + 1; j < n; j++)
      e[i * n + j] = q[i] * q[j] / (1.0 + (q[i] - q[j]) * (q[i] - q[j]));
}

// Column sums of the strict lower triangle, outer loop over columns, the row
// loop starting below the diagonal and counting down.
DPGEN_KERNEL void tri_colsum_down(DPGEN_IN const double* a, DPGEN_OUT double* c, int n) {
  for (int j = 0; j < n; ++j) {
    double s = 0.0;
    for (int i = n - 1; i > j; --i)
      s += std::sin(a[i * n + j]);
    c[j] = s;
  }
}

// A band: bounds that clip a window around the row with std::min/std::max.
DPGEN_KERNEL void tri_band_window(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int w) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - w); j < std::min(n, i + w + 1); ++j)
      s += a[j] * a[j] * (1.0 + 0.1 * (j - i));
    out[i] = s;
  }
}
