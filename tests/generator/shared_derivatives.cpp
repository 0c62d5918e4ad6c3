// A local used more than once: its derivative is shared by the partial's
// uses, and dpgen names it (`x2_d0`) where a partial uses it twice, so a
// chain of such locals prints in linear size; before, 14 of them ran the
// generator out of memory (a tree of 3^13 copies). A value stored and read
// back likewise becomes a local (`b_1`) where it is read back.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc
// RUN: FileCheck %s --input-file %t/shared_derivatives_adjoint.cpp
// RUN: wc -c < %t/shared_derivatives_adjoint.cpp | awk '{ exit !($1 < 20000) }'
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void chain14(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    const double x1 = 0.1 * a[i];
    const double x2 = x1 * x1 + x1;
    const double x3 = x2 * x2 + x2;
    const double x4 = x3 * x3 + x3;
    const double x5 = x4 * x4 + x4;
    const double x6 = x5 * x5 + x5;
    const double x7 = x6 * x6 + x6;
    const double x8 = x7 * x7 + x7;
    const double x9 = x8 * x8 + x8;
    const double x10 = x9 * x9 + x9;
    const double x11 = x10 * x10 + x10;
    const double x12 = x11 * x11 + x11;
    const double x13 = x12 * x12 + x12;
    const double x14 = x13 * x13 + x13;
    b[i] = x14;
  }
}

DPGEN_KERNEL void readback_chain(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = 0.1 * a[i];
    b[i] = b[i] * b[i] + b[i];
    b[i] = b[i] * b[i] + b[i];
    b[i] = b[i] * b[i] + b[i];
  }
}

// The interior loop of chain14's adjoint, after the locals x1..x13:
// CHECK-LABEL: void chain14_adjoint(
// CHECK: auto interior =
// CHECK: const double x2_d0 = x1 * 0.1 + x1 * 0.1 + 0.1;
// CHECK-NEXT: const double x3_d1 = x2 * x2_d0 + x2 * x2_d0 + x2_d0;
// CHECK: const double x13_d11 = x12 * x12_d10 + x12 * x12_d10 + x12_d10;
// CHECK-NEXT: acc += (x13 * x13_d11 + x13 * x13_d11 + x13_d11) * b_adj[i];
// CHECK-LABEL: void readback_chain_adjoint(
// CHECK: auto interior =
// CHECK: const double b_1 = 0.1 * a[i];
// CHECK-NEXT: const double b_2 = b_1 * b_1 + b_1;
// CHECK-NEXT: const double b_3 = b_2 * b_2 + b_2;
// CHECK-NEXT: const double b_2_d0 = b_1 * 0.1 + b_1 * 0.1 + 0.1;
// CHECK-NEXT: const double b_3_d1 = b_2 * b_2_d0 + b_2 * b_2_d0 + b_2_d0;
// CHECK-NEXT: acc += (b_3 * b_3_d1 + b_3 * b_3_d1 + b_3_d1) * b_adj[i];
// CHECK-LABEL: void readback_chain_parallel_forward(
// CHECK: const double b_1 = 0.1 * a[i];
// CHECK-NEXT: const double b_2 = b_1 * b_1 + b_1;
// CHECK-NEXT: const double b_3 = b_2 * b_2 + b_2;
// CHECK-NEXT: b[i] = b_3 * b_3 + b_3;
