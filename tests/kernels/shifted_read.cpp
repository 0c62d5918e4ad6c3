// A read shifted by a size argument, `a[i + shift]`: with a negative shift the
// first cells read before the start of `a`. The op's size checks bound both
// ends of what the kernel reaches (tests/torch/test_ops.py, OtherShapes), as does
// its checked entry point (tests/kernels/checked_entry_test.cpp).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void shifted_read(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int shift) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i + shift] * a[i + shift] + 0.5 * a[i + shift + 1];
}
