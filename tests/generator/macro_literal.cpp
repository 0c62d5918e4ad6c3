// Real literals that come from macros of a header the kernel includes are
// printed as their definitions spell them: the generated adjoint does not
// include that header (it had `CFL_COEF` by name and did not compile).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --tangent %s --out-dir %t -- -I%runtime_inc -I%S
// RUN: FileCheck %s --input-file %t/macro_literal_adjoint.cpp
// RUN: FileCheck %s --input-file %t/macro_literal_tangent.cpp
// CHECK-NOT: CFL_COEF
// CHECK-NOT: HALF
// CHECK: 0.25
#include "dpgen/annotate.hpp"
#include "macro_literal.h"

DPGEN_KERNEL void macro_literal(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = CFL_COEF * u[i] * u[i] + HALF(u[i - 1] * u[i + 1]);
}
