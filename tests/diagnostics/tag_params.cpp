// Unnamed parameters: only a tag (a value of an empty class at namespace
// scope, or a std::integral_constant) may be unnamed; the generated functions
// take it by const reference and declare its class (accepted forms:
// tests/modern/kernels/tag_*.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
// RUN: %dpgen %S/../modern/kernels/tag_dispatch.cpp --out-dir %t -- -I%runtime_inc
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/tag_dispatch_adjoint.hpp
#include "dpgen/annotate.hpp"

struct Weights {
  double w = 1.0;
};

// CHECK-DAG: tag_params.cpp:[[@LINE+1]]:{{[0-9]+}}: error: every kernel parameter needs a name (an unnamed one may only be an unannotated tag: a value of an empty class type) [dpgen-signature]
DPGEN_KERNEL void not_empty(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, Weights) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i];
}

// CHECK-DAG: tag_params.cpp:[[@LINE+1]]:{{[0-9]+}}: error: every kernel parameter needs a name
DPGEN_KERNEL void unnamed_int(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, int) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i];
}

// HEADER: // The kernels' tag types (a declaration is enough).
// HEADER-NEXT: struct XDir;
// HEADER-NEXT: struct YDir;
// HEADER: void sweep_adjoint(const double* u, double* u_adj, const double* out_adj, int nx, int ny, double c,
// HEADER-NEXT: const XDir& dpgen_tag_5);
