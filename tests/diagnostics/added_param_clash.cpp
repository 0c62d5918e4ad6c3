// Parameters dpgen adds to the generated signatures (the new values of a
// DPGEN_INOUT array, `u_new`; the size of a std::vector, `v_size`) must not
// take the name of one of the kernel's own.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <vector>

DPGEN_KERNEL void twin_clash(int u_new, DPGEN_INOUT double* u, int n) {
  // CHECK: added_param_clash.cpp:[[@LINE-1]]:61: error: parameter 'u_new' clashes with the name dpgen uses for the new values of in-place array 'u' [dpgen-signature]
  for (int i = 0; i < n; ++i)
    u[i] = 2.0 * u[i] + u_new;
}

DPGEN_KERNEL void size_clash(int v_size, DPGEN_IN const std::vector<double>& v,
                             DPGEN_OUT double* w) {
  // CHECK: added_param_clash.cpp:[[@LINE-2]]:78: error: parameter 'v_size' clashes with the size dpgen passes for vector 'v' [dpgen-signature]
  for (int i = 0; i < v_size; ++i)
    w[i] = v[i];
}
