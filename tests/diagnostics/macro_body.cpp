// A kernel body produced by a macro.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#define SCALE_BODY(OUT, IN, N)                                                                     \
  {                                                                                                \
    for (int i = 0; i < N; ++i)                                                                    \
      OUT[i] = 2.0 * IN[i];                                                                        \
  }

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) SCALE_BODY(out, a, n)
// CHECK: macro_body.cpp:[[@LINE-1]]:77: error: the body of kernel 'k' comes from macro 'SCALE_BODY': write the loops out
