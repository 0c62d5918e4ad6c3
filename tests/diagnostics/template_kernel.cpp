// A kernel that is a template.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

template <typename T>
DPGEN_KERNEL void k(DPGEN_IN const T* a, DPGEN_OUT T* out, int n) {
  // CHECK: template_kernel.cpp:[[@LINE-1]]:19: error: a DPGEN_KERNEL must not be a template
  for (int i = 0; i < n; ++i)
    out[i] = a[i];
}
