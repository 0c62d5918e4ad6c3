// An output summed into by a loop and then rescaled in place: the element
// holds two values in turn, which the adjoint cannot tell apart (it used to
// fold the rescaling into the initial value: a silently wrong adjoint).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void half_sum_of_squares(DPGEN_IN const double* a, DPGEN_OUT double* loss, int n) {
  *loss = 0;
  for (int i = 0; i < n; ++i)
    *loss += a[i] * a[i];
  *loss = *loss * 0.5;
  // CHECK: rescale_after_reduction.cpp:[[@LINE-1]]:11: error: output 'loss' is read here after line 12 wrote it, and written again on line 13: an output holds one value per element
  // The write-once rule is checked too, and its error reported in the same run:
  // CHECK: rescale_after_reduction.cpp:[[@LINE-3]]:3: error: output 'loss' is also written on line 10 in another loop nest
  // CHECK: 2 errors generated.
}
