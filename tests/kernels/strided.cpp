// Unusual affine maps: a stride-2 read, a reversed read, a non-affine read
// (i*i, scatter form), an inner loop writing two outputs per outer
// iteration, and a counter used as a value.
#include "test_kernels.hpp"

DPGEN_KERNEL void strided(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2; ++j) {
      double mirrored = a[2 * n - 1 - 2 * i - j];
      double coarse = a[2 * i] * static_cast<double>(i);
      out[2 * i + j] = mirrored * (j + 1) + coarse * a[(i * i) % n] + (i > 0 ? a[2 * i - 1] : 0.0);
    }
}
