// Two stores of one iteration to planes of a view that may be the same
// plane (v(0, j, i) and v(m, j, i): the same element where m == 0): dpgen
// cannot compare a view's layout (its plane stride is no size of the
// kernel), so it refuses where a flat array would get the condition m != 0
// on the earlier store. Different constant planes, v(0, j, i) and v(8, j, i),
// are apart (tests/styles/table_offsets.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc -I%S/../styles 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

DPGEN_KERNEL void two_planes(DPGEN_IN grid::Pops3D<const double> u, DPGEN_OUT grid::Pops3D<double> v,
                             int m) {
  for (int j = 0; j < u.ny; ++j)
    for (int i = 0; i < u.nx; ++i) {
      v(0, j, i) = u(0, j, i);
      v(m, j, i) = 2.0 * u(0, j, i);
      // CHECK: view_planes_same_iteration.cpp:[[@LINE-1]]:7: error: output 'v' may be written twice in one iteration (first at line {{[0-9]+}}); write each element once
    }
}
