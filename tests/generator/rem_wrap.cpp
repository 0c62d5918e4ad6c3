// A periodic wrap written with %, `(i + 1) % n` for i in [0, n), is the
// choice it equals (i + 1 < n ? i + 1 : i + 1 - n): gather form, no remark.
// A remainder whose range the loops do not bound to [k n, (k + 2) n)
// (`(i + 3) % n`, n may be 1) stays as written: correct but scatter form; the
// remark says how to get the gather form. Both adjoints compile and are written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 3
// RUN: FileCheck %s --check-prefix=GATHER --input-file %t/rem_wrap_adjoint.cpp
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void forward_difference(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[(i + 1) % n] - a[i];
  // CHECK-NOT: remark: read 'a[(i + 1) % n]'
  // GATHER: // out[i] reads a[(i + 1) % n] at i = c_i + n - 1: acc += ∂out[i]/∂a[(i + 1) % n] · out_adj[i]
}

DPGEN_KERNEL void third_neighbour(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[(i + 3) % n] - a[i];
  // CHECK: rem_wrap.cpp:[[@LINE-1]]:14: remark: read 'a[(i + 3) % n]' in kernel 'third_neighbour' has an index that dpgen cannot invert (not affine in the loop counters, or piecewise on a condition it cannot bound): its adjoint is computed in scatter form, serially (for the gather form, write a periodic wrap as a conditional index: i == n - 1 ? 0 : i + 1)
}
