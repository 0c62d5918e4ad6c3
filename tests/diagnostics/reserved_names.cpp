// Names the generated code needs for the kernel's own arrays are not free
// for other parameters (issue 20, defect 2): the adjoint of 'u' is 'u_adj'
// and its tangent 'u_dot'; 'dpgen_' is reserved for generated helpers; a C++
// keyword cannot name a parameter of the (C++) adjoint. Every such parameter
// is reported in one run, and nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc -x c -DAS_C 2>&1 | FileCheck %s --check-prefix=C
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#ifndef AS_C
DPGEN_KERNEL void k(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double u_adj,
                    double out_dot, int dpgen_n) {
  // CHECK: reserved_names.cpp:[[@LINE-2]]:84: error: parameter 'u_adj' has the name that the generated adjoint gives the adjoint of array 'u'; rename it
  // CHECK: reserved_names.cpp:[[@LINE-2]]:28: error: parameter 'out_dot' has the name that the generated tangent gives the tangent of array 'out'; rename it
  // CHECK: reserved_names.cpp:[[@LINE-3]]:41: error: parameter 'dpgen_n': names starting with 'dpgen_' are reserved for generated code; rename it
  for (int i = 0; i < n; ++i)
    out[i] = u[i] * u_adj * out_dot * dpgen_n;
}
#else
DPGEN_KERNEL void kc(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double this) {
  // C: reserved_names.cpp:[[@LINE-1]]:85: error: parameter 'this' is a C++ keyword, and the generated adjoint is C++; rename it
  int i;
  for (i = 0; i < n; ++i)
    out[i] = u[i] * this;
}
#endif
