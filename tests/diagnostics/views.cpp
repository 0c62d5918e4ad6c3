// Array views dpgen cannot prove to be layouts, or takes no further, are
// errors that say why; a view class the kernel file defines itself cannot be
// seen by the generated files. Nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include "views.hpp"

DPGEN_KERNEL void diagonal(DPGEN_IN const double* u, DPGEN_OUT Diagonal v, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      v(j, i) = 2.0 * u[j * n + i];
  // CHECK: views.cpp:[[@LINE-1]]:7: error: view 'v': Diagonal::operator() does not map distinct indices to distinct elements as a layout does: indices share the stride 1 [dpgen-signature]
}

DPGEN_KERNEL void scrambled(DPGEN_IN Scrambled u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    v[i] = u(i);
  // CHECK: views.cpp:[[@LINE-1]]:12: error: view 'u': Scrambled::operator() does not map distinct indices to distinct elements as a layout does: its index is not a sum of the indices times members or constants [dpgen-signature]
}

DPGEN_KERNEL void five(DPGEN_IN Five u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    v[i] = u(0, 0, 0, 0, i);
  // CHECK: views.cpp:[[@LINE-1]]:12: error: view 'u' is indexed with 5 indices: dpgen takes views of rank 1 to 4 [dpgen-unsupported]
}

struct Local {
  double* p;
  double& operator()(int i) const { return p[i]; }
};

DPGEN_KERNEL void local_class(DPGEN_IN const double* u, DPGEN_OUT Local v, int n) {
  // CHECK: views.cpp:[[@LINE-1]]:73: error: view 'v' has a class defined in the kernel file ('Local'): the generated files must see its definition, so move it to a header the kernel file includes [dpgen-signature]
  for (int i = 0; i < n; ++i)
    v(i) = u[i];
}

DPGEN_KERNEL void annotated_object(DPGEN_IN Box2 b, DPGEN_OUT double* v) {
  // CHECK: views.cpp:[[@LINE-1]]:50: error: parameter 'b' of class 'Box2' is no array view (it has no operator() or operator[]): DPGEN_IN/DPGEN_OUT do not apply to it [dpgen-signature]
  v[0] = 1.0;
}
