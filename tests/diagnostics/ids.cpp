// Every diagnostic ends with its id (clang-tidy style): the rule of the kernel
// subset it is about. One kernel per id here; other tests match sentences.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

#include <cmath>

// CHECK-DAG: ids.cpp:[[@LINE+1]]:{{[0-9]+}}: error: a DPGEN_KERNEL returns void, float or double, not 'long'; {{.*}} [dpgen-signature]
DPGEN_KERNEL long returns(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i];
  return 0;
}

// CHECK-DAG: ids.cpp:[[@LINE+1]]:{{[0-9]+}}: error: parameter 'dpgen_n': names starting with 'dpgen_' are reserved for generated code; rename it [dpgen-name]
DPGEN_KERNEL void named(DPGEN_IN const double* a, DPGEN_OUT double* b, int dpgen_n) {
  for (int i = 0; i < dpgen_n; ++i)
    b[i] = a[i];
}

DPGEN_KERNEL void looped(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; i *= 2)
    // CHECK-DAG: ids.cpp:[[@LINE-1]]:{{[0-9]+}}: error: loop increment must be {{.*}} [dpgen-loop]
    b[i] = a[i];
}

DPGEN_KERNEL void called(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = std::lgamma(a[i]);
  // CHECK-DAG: ids.cpp:[[@LINE-1]]:12: error: call to 'lgamma', which dpgen cannot differentiate; {{.*}} [dpgen-call]
}

DPGEN_KERNEL void jumps(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i];
  goto done;
  // CHECK-DAG: ids.cpp:[[@LINE-1]]:3: error: 'goto' is outside the kernel subset [dpgen-unsupported]
done:;
}

DPGEN_KERNEL void twice(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[0] = a[i];
  // CHECK-DAG: ids.cpp:[[@LINE-1]]:5: error: output 'b' is written at the same index by every {{.*}} [dpgen-write-once]
}

DPGEN_KERNEL void buffered(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  double t[128];
  for (int i = 0; i < n - 1; ++i)
    t[i] = a[i];
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: ids.cpp:[[@LINE+1]]:{{[0-9]+}}: error: line buffer 't' is read at 't[i]' {{.*}} [dpgen-buffer]
    b[i] = t[i];
}
