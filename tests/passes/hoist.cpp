// --print-after=hoist: the loop-invariant subexpressions each generated
// function defines once before its loops (hoist.hpp), and the planned terms
// rewritten to use them; emit prints both as they are.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=hoist %s --out-dir %t -- -I%runtime_inc | FileCheck %s
// RUN: FileCheck %s --check-prefix=CODE < %t/hoist_adjoint.cpp
#include "dpgen/annotate.hpp"

// The adjoint: the divisions the upwind switch copies into its partials go
// (`1.0 / dx`, named inv_dx), once however often they occur; so does a
// coefficient of parameters. An integer division stays where it is (it may
// trap where the source would not run it), and so does `u[i] / dx` (it reads
// an array). The forward hoists its own coefficient, numbered on its own.
// CHECK-LABEL: hoisted in flux_limit
// CHECK-NEXT: adjoint:
// CHECK-NEXT: inv_dx = 1.0 / dx
// CHECK-NEXT: hoisted1 = nu / (dx * dx)
// CHECK-NEXT: forward:
// CHECK-NEXT: hoisted0 = nu / (dx * dx)
// CHECK-NEXT: interior term of u, block 0: u[i] > 0.0 ? inv_dx : 0.0
// CHECK-NEXT: interior term of u, block 1: u[i] > 0.0 ? 0.0 : inv_dx
// CHECK-NEXT: interior term of u, block 2: hoisted1
// CHECK-NOT: n / 2
// CHECK-LABEL: hoisted in two_pass
DPGEN_KERNEL void flux_limit(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double dx,
                             double nu) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = (u[i] > 0.0 ? u[i] / dx : u[i + 1] / dx) + u[i - 1] * (nu / (dx * dx)) +
             u[i] / static_cast<double>(n / 2);
}
// CODE-LABEL: void flux_limit_adjoint(
// CODE: // loop-invariant, hoisted: computed once here, the same expressions as in the loops below
// CODE-NEXT: const auto inv_dx = 1.0 / dx;
// CODE-NEXT: const auto hoisted1 = nu / (dx * dx);
// CODE: acc += (u[i] > 0.0 ? inv_dx : 0.0) * out_adj[i];
// CODE: acc += 1.0 / static_cast<double>(n / 2) * out_adj[i];
// CODE-LABEL: void flux_limit_parallel_forward(
// CODE: const auto hoisted0 = nu / (dx * dx);
// CODE: u[i - 1] * hoisted0
// CODE-LABEL: void two_pass_nest1_adjoint(
// CODE: const auto hoisted0 = 1.0 / (2.0 * dx);
// CODE: (u[i] + u[i]) * hoisted0
// CODE-NOT: / hoisted0
// CODE-LABEL: void two_pass_nest2_adjoint(
// CODE-LABEL: void two_pass_parallel_forward(
// CODE: const auto hoisted0 = 2.0 * dx;
// CODE: w[i] = u[i] * u[i] / hoisted0;

// A kernel with a work array (w): each stage of its staged adjoint hoists
// its own; the forward's (here the parallel forward's; a staged adjoint's
// recompute, where it has one, prints the same plan) are numbered apart.
// Stage 0's partial of u[i] * u[i] / (2.0 * dx) divides a value read in the
// loop by an invariant: derive writes it as a product with 1 / (2.0 * dx),
// hoisted, where the forward divides as the kernel does.
// CHECK-NEXT: stage 0
// CHECK-NEXT: adjoint:
// CHECK-NEXT: hoisted0 = 1.0 / (2.0 * dx)
// CHECK-NEXT: stage 1
// CHECK-NEXT: adjoint:
// CHECK-NEXT: inv_dx = 1.0 / dx
// CHECK-NEXT: forward:
// CHECK-NEXT: hoisted0 = 2.0 * dx
DPGEN_KERNEL void two_pass(DPGEN_IN const double* u, DPGEN_OUT double* w, DPGEN_OUT double* out,
                           int n, double dx) {
  for (int i = 0; i < n; ++i)
    w[i] = u[i] * u[i] / (2.0 * dx);
  for (int i = 1; i < n; ++i)
    out[i] = (w[i] - w[i - 1]) / dx;
}

// Factored partials the same up to sign share one sum, the seeds of -c
// subtracted from it: one product per cell instead of one per sign.
// CODE-LABEL: void central_adjoint(
// CODE: double acc_s0 = -0.0;
// CODE-NOT: acc_s1
// CODE: acc_s0 += out_adj[i];
// CODE: acc_s0 -= out_adj[i];
// CODE: acc_s0 -= out_adj[i];
// CODE-NEXT: }
// CODE-NEXT: acc += c * acc_s0;
// CODE-NEXT: a_adj[c_i] += acc;
DPGEN_KERNEL void central(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double c) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = (a[i + 1] - a[i - 1]) * c - a[i] * c;
}
