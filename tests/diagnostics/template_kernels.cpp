// Template kernels: an adjoint per instantiation the file makes; a template
// that is never instantiated has no types to generate for.
// (accepted forms: tests/modern/kernels/tmpl_diffuse.cpp, tmpl_dir.cpp)
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
// RUN: %dpgen --tangent %S/../modern/kernels/tmpl_dir.cpp --out-dir %t -- -I%runtime_inc
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/tmpl_dir_adjoint.hpp
// RUN: FileCheck %s --check-prefix=TANGENT --input-file %t/tmpl_dir_tangent.hpp
#include "dpgen/annotate.hpp"

// CHECK: template_kernels.cpp:[[@LINE+2]]:19: error: template kernel 'scale' is not instantiated in this file: dpgen writes an adjoint per instantiation, so instantiate it here (template void scale<double>(...);) or call it [dpgen-signature]
template <typename Real>
DPGEN_KERNEL void scale(DPGEN_IN const Real* a, DPGEN_OUT Real* b, int n, Real s) {
  for (int i = 0; i < n; ++i)
    b[i] = s * a[i];
}

// HEADER: /// Adjoint of gradient<double, 0> (tmpl_dir.cpp:8).
// HEADER-NEXT: void gradient_double_0_adjoint(const double* p, double* p_adj, const double* g_adj, int nx, int ny,
// HEADER: template <typename Real, int Dir>
// HEADER-NEXT: void gradient_adjoint(const Real* p, Real* p_adj, const Real* g_adj, int nx, int ny, Real inv_2h);
// HEADER-NEXT: template <>
// HEADER-NEXT: inline void gradient_adjoint<double, 0>(const double* p, double* p_adj, const double* g_adj, int nx,
// HEADER: gradient_double_0_adjoint(p, p_adj, g_adj, nx, ny, inv_2h);
// HEADER: inline void gradient_adjoint<double, 1>(
// TANGENT: void gradient_tangent(const Real* p, const Real* p_dot, Real* g, Real* g_dot, int nx, int ny,
// TANGENT: inline void gradient_tangent<double, 1>(
