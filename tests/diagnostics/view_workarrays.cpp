// Views as work arrays (outputs a later loop reads): the adjoint finds the
// elements of its buffers by running the stores' loops before it recomputes
// them, so a store to a view output, or one that reads a view work array
// (its value or its condition), must not sit under a condition that reads
// what the kernel writes; and a later loop must not read elements no loop
// writes (as for pointers).
// Nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include "../styles/include/user_views.hpp"

DPGEN_KERNEL void guarded_by_written(DPGEN_IN grid::View2D<const double> u,
                                     DPGEN_OUT grid::View2D<double> w,
                                     DPGEN_OUT grid::View2D<double> v, int n) {
  for (int i = 0; i < n; ++i)
    w(0, i) = u(0, i) * u(0, i);
  for (int i = 0; i < n; ++i)
    if (w(0, i) > 1.0)
      v(0, i) = 2.0 * w(0, i);
  // CHECK: view_workarrays.cpp:[[@LINE-1]]:7: error: this store writes a view the adjoint recomputes into a buffer of its own (laid out like the view's seed), under a condition that reads what the kernel writes: the adjoint finds the buffer's elements before it recomputes them; make the condition read inputs only [dpgen-work-array]
}

DPGEN_KERNEL void reads_unwritten(DPGEN_IN grid::View2D<const double> u,
                                  DPGEN_OUT grid::View2D<double> w,
                                  DPGEN_OUT grid::View2D<double> v, int n) {
  for (int i = 0; i < n; ++i)
    w(0, i) = u(0, i) * u(0, i);
  for (int i = 0; i < n; ++i)
    v(0, i) = w(0, i + 1) - w(0, i);
  // CHECK: view_workarrays.cpp:[[@LINE-1]]:15: error: reads work array 'w' at elements no earlier loop writes
}

DPGEN_KERNEL void pointer_store_guarded_by_view(DPGEN_IN grid::View2D<const double> u,
                                                DPGEN_OUT grid::View2D<double> w,
                                                DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    w(0, i) = u(0, i) * u(0, i);
  for (int i = 0; i < n; ++i)
    if (w(0, i) > 1.0)
      v[i] = 2.0 * u(0, i);
  // CHECK: view_workarrays.cpp:[[@LINE-1]]:7: error: this store reads a view the adjoint recomputes into a buffer of its own (laid out like the view's seed), under a condition that reads what the kernel writes
}
