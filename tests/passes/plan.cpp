// --print-after=plan: the loops of the adjoint before anything is printed:
// per input, the cell box, the branch-free interior, edges that may reach
// into it, fusion of inputs with the same cell box or boxes a constant apart,
// and the parallel test;
// then the forward forms' loops (the tangent, the torch ops' forward): the
// kernel's own nests, parallel where every store sets its element, split
// where their boundary conditions are decided.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=plan %s --out-dir %t -- -I%runtime_inc | FileCheck %s
#include "dpgen/annotate.hpp"

// Two inputs whose cell boxes differ by constants (a: [0, n), b: [1, n - 1)):
// one fused loop over the box around both, its interior inside each one's
// (a's 3-point reads leave two cells at each end to the edge code, where b's
// terms apply only inside b's box); and a loop of each alone, run when the
// other's adjoint is null.
// CHECK-LABEL: plan of blend
// CHECK-NEXT: input a
// CHECK-NEXT: step fused
// CHECK-NEXT: cells of [a, b]
// CHECK-NEXT: i in [0, n)
// CHECK-NEXT: interior {i: [2, n - 2)}
// CHECK-NEXT: parallel: unit stride
// CHECK-NEXT: cells of [a]
// CHECK-NEXT: i in [0, n)
// CHECK-NEXT: interior {i: [2, n - 2)}
// CHECK-NEXT: parallel: unit stride
// CHECK-NEXT: cells of [b]
// CHECK-NEXT: i in [1, n - 1)
// CHECK: forward loops of blend
// CHECK-NEXT: nest 1: parallel, i in [1, n - 1)
DPGEN_KERNEL void blend(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* c,
                        int n) {
  for (int i = 1; i < n - 1; ++i)
    c[i] = a[i - 1] + a[i + 1] - 2.0 * b[i];
}

// A MAC-grid divergence (as tests/kernels/peel_kernels.cpp's peel_near_boxes_mac): u's cells
// are rows [0, ny - 1), v's columns [0, nx - 1); one loop over the box around both, whose
// interior lies inside each.
// CHECK-LABEL: plan of mac_div
// CHECK-NEXT: input u
// CHECK-NEXT: step fused
// CHECK-NEXT: cells of [u, v]
// CHECK-NEXT: i in [0, nx)
// CHECK-NEXT: j in [0, ny)
// CHECK-NEXT: interior {i: [1, nx - 1); j: [1, ny - 1)}
// CHECK: cells of [u]
// CHECK-NEXT: i in [0, nx)
// CHECK-NEXT: j in [0, ny - 1)
// CHECK: cells of [v]
// CHECK-NEXT: i in [0, nx - 1)
// CHECK-NEXT: j in [0, ny)
DPGEN_KERNEL void mac_div(DPGEN_IN const double* u, DPGEN_IN const double* v, DPGEN_OUT double* div,
                          int nx, int ny) {
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx - 1; ++i) {
      const int k = j * nx + i;
      div[k] = u[k + 1] - u[k] + v[k + nx] - v[k];
    }
}

// Cell boxes that differ by more than constants (b's ends at min(n - 1, m)):
// a loop each, as the box around both could hold many cells of neither.
// CHECK-LABEL: plan of apart
// CHECK-NEXT: input a
// CHECK-NEXT: step
// CHECK-NEXT: cells of [a]
// CHECK-NEXT: i in [0, n)
// CHECK-NEXT: interior {i: [2, n - 2)}
// CHECK-NEXT: parallel: unit stride
// CHECK-NEXT: input b
// CHECK-NEXT: step
// CHECK-NEXT: cells of [b]
// CHECK-NEXT: i in [1, min(n - 1, m))
DPGEN_KERNEL void apart(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* c,
                        int n, int m) {
  for (int i = 1; i < n - 1; ++i)
    c[i] = a[i - 1] + a[i + 1] + (i < m ? b[i] : 0.0);
}

// A 2D layout: the parallel test is the mixed-radix one (columns step 1 and
// reach nx - 1, rows step nx).
// CHECK-LABEL: plan of grad2d
// CHECK-NEXT: input p
// CHECK-NEXT: step
// CHECK-NEXT: cells of [p]
// CHECK-NEXT: i in [0, nx)
// CHECK-NEXT: j in [0, ny)
// CHECK-NEXT: interior {i: [0, nx); j: [2, ny - 2)}
// CHECK-NEXT: parallel: radix dim 1 step 1 reach 0
// CHECK-NEXT: parallel: radix dim 0 step nx reach hi_i - lo_i - 1
DPGEN_KERNEL void grad2d(DPGEN_IN const double* p, DPGEN_OUT double* g, int nx, int ny) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      g[j * nx + i] = p[(j + 1) * nx + i] - p[(j - 1) * nx + i];
}

// A nest that adds (`+=`) runs serially in the forward forms; a store outside
// every loop is a nest of its own; a nest after it that sets its elements is
// parallel again.
// CHECK-LABEL: forward loops of sums
// CHECK-NEXT: nest 1: serial (a store adds), j in [0, ny), i in [0, nx)
// CHECK-NEXT: nest 2: serial (no loop)
// CHECK-NEXT: nest 3: parallel, i in [0, nx)
DPGEN_KERNEL void sums(DPGEN_IN const double* a, DPGEN_OUT double* col, DPGEN_OUT double* first,
                       DPGEN_OUT double* twice, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      col[i] += a[j * nx + i];
  first[0] = a[0];
  for (int i = 0; i < nx; ++i)
    twice[i] = 2.0 * a[i];
}

// The forward forms split their loops where the stores' index conditions are
// decided (peel_forward): the interior's bounds beyond the loops' own (`*`:
// none on that side) and its stores, the wall rows' branch and the wrap gone
// (peel_walls2d of the kernels tests/kernels/peel_test.cpp runs).
// RUN: %dpgen --print-after=plan %S/../kernels/peel_kernels.cpp --out-dir %t -- \
// RUN:   -I%runtime_inc -I%S/../kernels | FileCheck %s --check-prefix=PEEL
// PEEL-LABEL: forward loops of peel_walls2d
// PEEL-NEXT: nest 1: parallel, j in [0, ny), i in [0, nx)
// PEEL-NEXT: split, interior {i: [*, nx - 1); j: [1, ny - 1)}
// PEEL-NEXT: interior: out[j * nx + i] = a[j * nx + ip] * a[(j + 1) * nx + i] - a[(j - 1) * nx + i]{{$}}
// PEEL-NOT: interior:
// PEEL-LABEL: forward loops of peel_coef
