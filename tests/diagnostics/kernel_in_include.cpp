// A kernel defined in an included file gets no adjoint from a run on the file
// that includes it: a warning names it and says what to do (until session 21
// it was left out silently). The kernels of the file itself are written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | FileCheck --check-prefix=FILES %s
// RUN: %not grep -q included_square %t/kernel_in_include_adjoint.hpp
#include "Inputs/kernel_in_include.hpp"

// CHECK: kernel_in_include.hpp:5:26: warning: kernel 'included_square' is defined in a file
// CHECK-SAME: that 'kernel_in_include.cpp' includes: dpgen writes adjoints for the kernels
// CHECK-SAME: defined in the file it is run on; run it on the file that defines this kernel as
// CHECK-SAME: well [dpgen-kernel-elsewhere]
// CHECK-NOT: error
//
// FILES: kernel_in_include_adjoint.cpp
// FILES: kernel_in_include_adjoint.hpp
DPGEN_KERNEL void twice_square(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = 2.0 * a[i];
}
