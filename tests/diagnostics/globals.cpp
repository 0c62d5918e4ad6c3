// Globals a kernel reads: unmarked ones are constants read by name, DPGEN_IN
// ones are differentiated through the global pointer <name>_adj (accepted
// forms: tests/modern/kernels/global_*.cpp). What is refused:
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
// RUN: %dpgen %S/../modern/kernels/global_coef.cpp --out-dir %t -- -I%runtime_inc
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/global_coef_adjoint.hpp
// RUN: FileCheck %s --check-prefix=SOURCE --input-file %t/global_coef_adjoint.cpp
#include "dpgen/annotate.hpp"

// CHECK-DAG: globals.cpp:[[@LINE+1]]:15: error: global 'hidden' is static: the generated files, another translation unit, cannot read it; give it external linkage or pass it as a parameter [dpgen-global]
static double hidden = 2.0;
// CHECK-DAG: globals.cpp:[[@LINE+1]]:19: error: global 'result' is marked DPGEN_OUT; a global is read only: unmarked (a constant) or DPGEN_IN (differentiated) [dpgen-global]
DPGEN_OUT double* result = nullptr;

DPGEN_KERNEL void uses_static(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = hidden * a[i];
}

DPGEN_KERNEL void writes_global(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i] + result[i];
}

// HEADER: // The adjoint of each global marked DPGEN_IN: point it at storage of the global's size
// HEADER: extern double* g_stencil_adj;
// HEADER-NEXT: extern double* g_kappa_adj;
// HEADER: void varcoef_smooth_adjoint(const double* u, double* u_adj, const double* out_adj, int n);
// SOURCE: extern double g_dx;
// SOURCE-NEXT: extern double g_stencil[3];
// SOURCE-NEXT: double* g_stencil_adj = nullptr;
// SOURCE-NEXT: extern double* g_kappa;
// SOURCE-NEXT: double* g_kappa_adj = nullptr;
