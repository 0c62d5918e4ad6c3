// A read shifted by a size argument, `a[i + shift]`, from cell 1 (cell 0 is a
// boundary the kernel leaves alone): shift -1 is the smallest that stays in `a`,
// -2 reads before its start. The op's size checks bound both
// ends of what the kernel reaches (tests/torch/test_ops.py, OtherShapes), as does
// its checked entry point (tests/kernels/checked_entry_test.cpp).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void shifted_read(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int shift) {
  for (int i = 1; i < n; ++i)
    out[i] = a[i + shift] * a[i + shift] + 0.5 * a[i + shift + 1];
}
