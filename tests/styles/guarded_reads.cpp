// Reads that only a guard keeps in bounds, as users write boundaries: a local
// made after a boundary `continue` that a later condition reads (the tangent
// and the parallel forward computed it before the boundary test: q[-1] at
// i = 0), a work array read under a guard on the sizes (the adjoint copied a
// seed as long as the guarded read reached: w_adj[1] of n = 0), and a loop
// that runs once beside a faster counter of the same step (its run-time
// layout check threw for every n >= 2). Their tests read arrays of exactly
// the kernel's sizes, so the sanitizer build sees a read out of bounds.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void limiter_after_continue(DPGEN_IN const double* q, DPGEN_OUT double* s, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0 || i == n - 1) {
      s[i] = 0.0;
      continue;
    }
    const double a = q[i] - q[i - 1], b = q[i + 1] - q[i];
    if (a * b > 0.0)
      s[i] = a;
    else
      s[i] = b * b;
  }
}

DPGEN_KERNEL void guarded_pair(DPGEN_IN const double* u, DPGEN_OUT double* w, DPGEN_OUT double* v,
                               int n) {
  for (int i = 0; i < n; ++i)
    w[i] = u[i] * u[i];
  if (n > 1)
    v[0] = w[0] + w[1];
}

DPGEN_KERNEL void unit_inner(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 1; ++c)
      v[i + c] = u[i + c] * u[i + c];
}
