// Less common shapes of the subset: an early return on a parameter, a loop
// counting down with an inclusive bound, a bool local as a branch condition,
// fmin/fmax, the counter used as a value, a local outside every loop that
// reads an input, and straight-line stores in disjoint ranges.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void edge_cases(DPGEN_IN const double* a, DPGEN_IN const double* b,
                             DPGEN_OUT double* out, DPGEN_OUT double* ends, int n, double s) {
  if (n < 2)
    return;
  const double a0 = a[0]; // a kernel-level local that reads an input
  ends[0] = a0 * b[n - 1];
  ends[1] = a[n - 1] - b[0];
  for (int i = n - 2; i >= 1; --i) {
    const bool left_half = 2 * i < n;
    const double x = s * i;
    double v = std::fmin(a[i - 1], a[i + 1]) + std::fmax(b[i], 0.25 * x);
    if (left_half)
      v *= a[i] + a0;
    out[i] = v;
  }
}
