// Line buffers (local arrays of more than 64 elements, VLAs) hold values
// within one iteration of the loops around all their uses (issue 20): a read
// of an element that no earlier loop of the same iteration wrote (past what
// the filling loop covered, or left from the previous iteration), a buffer
// carried from one iteration to the next, a recurrence through a buffer, an
// element written outside the buffer are errors, each in one run. Parsed as
// C (`-x c`), as VLA codes are.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc -x c -ferror-limit=0 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

// The filling loop stops one short of what the next loop reads (u1[i + 1]
// at i = n - 2 reads element n - 1, never written).
DPGEN_KERNEL void read_past_fill(DPGEN_IN const double* u, DPGEN_OUT double* r, int n) {
  double u1[256];
  for (int i = 0; i < n - 1; i++)
    u1[i] = u[i] * u[i];
  for (int i = 1; i < n - 1; i++)
    r[i] = u1[i - 1] + u1[i + 1];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:24: error: line buffer 'u1' is read at 'u1[i + 1]' (elements 2 to n - 1), and dpgen cannot prove that the earlier loops of the kernel wrote every element read (they write elements 0 to n - 2 (line [[@LINE-3]])){{.*}}[dpgen-buffer]
}

// The previous row's values: read before this row writes them.
DPGEN_KERNEL void previous_row(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double prev[nx];
  for (int j = 0; j < ny; j++) {
    for (int i = 0; i < nx; i++)
      out[j * nx + i] = a[j * nx + i] - prev[i];
    // CHECK: line_buffers.cpp:[[@LINE-1]]:41: error: line buffer 'prev' is read at 'prev[i]', and no earlier loop of an iteration of loop 'j' writes it{{.*}}[dpgen-buffer]
    for (int i = 0; i < nx; i++)
      prev[i] = a[j * nx + i];
  }
}

// Carried across the outer iterations: filled before the row loop, then
// rewritten by every row (each row reads the one before it).
DPGEN_KERNEL void carried_rows(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double line[nx];
  for (int i = 0; i < nx; i++)
    line[i] = a[i];
  for (int j = 1; j < ny; j++) {
    for (int i = 0; i < nx; i++)
      out[j * nx + i] = a[j * nx + i] - line[i];
    for (int i = 0; i < nx; i++)
      line[i] = a[j * nx + i];
    // CHECK: line_buffers.cpp:[[@LINE-1]]:7: error: line buffer 'line' is written at the same element 'line[i]' by every iteration of loop 'j'{{.*}}[dpgen-buffer]
  }
}

// A recurrence through a buffer in one loop, read before or after the store.
DPGEN_KERNEL void running(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[n];
  t[0] = a[0];
  for (int i = 1; i < n; i++) {
    t[i] = t[i - 1] + a[i];
    // CHECK: line_buffers.cpp:[[@LINE-1]]:12: error: line buffer 't' is read here and written on line [[@LINE-1]], in the same loop or later: a value carried from one iteration to the next{{.*}}[dpgen-read-after-write]
    out[i] = t[i];
  }
}

DPGEN_KERNEL void lagged(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[n];
  for (int i = 1; i < n; i++) {
    t[i] = a[i] * a[i];
    out[i] = t[i - 1];
    // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 't' is read at 't[i - 1]', an element this iteration does not write before (it writes 't[i]' on line [[@LINE-2]]): a value carried from another iteration of loop 'i' (a recurrence){{.*}}[dpgen-buffer]
  }
}

// Written past the end of a fixed buffer, for every size.
DPGEN_KERNEL void past_end(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[100];
  for (int i = 0; i < n; i++)
    t[i + 100] = a[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:5: error: line buffer 't' of 100 elements is written at 't[i + 100]' (elements 100 to n + 99), which dpgen finds is not always within the buffer [dpgen-buffer]
  for (int i = 0; i < n; i++)
    out[i] = t[i + 100];
}

// A data-dependent index.
DPGEN_KERNEL void gathered(DPGEN_IN const double* a, const int* idx, DPGEN_OUT double* out, int n) {
  double t[n];
  for (int i = 0; i < n; i++)
    t[i] = a[i];
  for (int i = 0; i < n; i++)
    out[i] = t[idx[i]];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 't' is indexed at 't[idx[i]]', which is not a polynomial{{.*}}[dpgen-buffer]
}

// An initializer, a two-dimensional buffer, an integer buffer.
DPGEN_KERNEL void shapes(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double z[128] = {0};
  // CHECK: line_buffers.cpp:[[@LINE-1]]:19: error: line buffer 'z' has an initializer{{.*}}
  double m[10][10];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:10: error: local array 'm' of type 'double[10][10]' is outside the kernel subset
  int k[n];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:7: error: local array 'k' of type 'int[n]' is outside the kernel subset: a line buffer{{.*}}
  for (int i = 0; i < n; i++)
    out[i] = a[i];
}

// A pointer to VLA rows must come from a cast of a flat array parameter,
// keeping the element type.
DPGEN_KERNEL void bad_casts(DPGEN_IN const double* u, const int* f, DPGEN_OUT double* out, int n) {
  const double (*w)[n] = (const double (*)[n])f;
  // CHECK: line_buffers.cpp:[[@LINE-1]]:18: error: pointer 'w' has elements of type 'const double', parameter 'f' of 'int'{{.*}}
  const double (*v)[n] = (const double (*)[n])(u + n);
  // CHECK: line_buffers.cpp:[[@LINE-1]]:18: error: pointer 'v' to arrays must be initialised with a cast of a flat array parameter{{.*}}
  for (int i = 0; i < n; i++)
    out[i] = u[i];
}

// Written only where a condition holds, read everywhere; and reused for a
// second purpose in the same iteration.
DPGEN_KERNEL void arms(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int c) {
  double tmp[100];
  if (c > 0) {
    for (int i = 0; i < n; ++i)
      tmp[i] = a[i];
  }
  for (int i = 0; i < n; ++i)
    out[i] = tmp[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 'tmp' is read at 'tmp[i]', and no earlier loop of the kernel writes it wherever this read runs (line [[@LINE-4]] writes it under a condition that may not hold here){{.*}}[dpgen-buffer]
}

DPGEN_KERNEL void reused(DPGEN_IN const double* a, DPGEN_OUT double* o1, DPGEN_OUT double* o2, int n) {
  double tmp[100];
  for (int i = 0; i < n; ++i)
    tmp[i] = a[i];
  for (int i = 0; i < n; ++i)
    o1[i] = tmp[i];
  for (int i = 0; i < n; ++i)
    tmp[i] = 2 * a[i] * a[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:5: error: line buffer 'tmp' is also written on line [[@LINE-5]] in another loop nest{{.*}}[dpgen-write-once]
  for (int i = 0; i < n; ++i)
    o2[i] = tmp[i];
}

// Round r5 (tests/adversary/r5_buffers.cpp has the accepted ones): an element
// overwritten after its fill, a fill of even elements or one skipping an
// element, a buffer first written with '+=', a fill one past a VLA's end,
// and a fill of interleaved pairs (not contiguous: dpgen cannot follow it).
DPGEN_KERNEL void overwrite0(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[200];
  for (int i = 0; i < n; ++i)
    t[i] = a[i];
  t[0] = 1.0;
  // CHECK: line_buffers.cpp:[[@LINE-1]]:3: error: line buffer 't' is also written on line [[@LINE-2]] in another loop nest{{.*}}[dpgen-write-once]
  for (int i = 0; i < n; ++i)
    out[i] = t[i] * a[i];
}

DPGEN_KERNEL void even_only(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[200];
  for (int i = 0; i < n; ++i)
    if (i % 2 == 0)
      t[i] = a[i];
  for (int i = 0; i < n; ++i)
    out[i] = t[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 't' is read at 't[i]', and no earlier loop of the kernel writes it wherever this read runs (line [[@LINE-3]] writes it under a condition that may not hold here){{.*}}[dpgen-buffer]
}

DPGEN_KERNEL void skip3(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[200];
  for (int i = 0; i < n; ++i) {
    if (i == 3)
      continue;
    t[i] = a[i];
  }
  for (int i = 0; i < n; ++i)
    out[i] = t[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 't' is read at 't[i]', and no earlier loop of the kernel writes it wherever this read runs (line [[@LINE-4]] writes it under a condition that may not hold here){{.*}}[dpgen-buffer]
}

DPGEN_KERNEL void plus_first(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[200];
  for (int i = 0; i < n; ++i)
    t[i] += a[i];
  for (int i = 0; i < n; ++i)
    out[i] = t[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 't' is read at 't[i]', and no earlier loop of the kernel writes it:{{.*}}[dpgen-buffer]
}

DPGEN_KERNEL void one_past(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[n];
  for (int i = 0; i <= n; ++i)
    t[i] = a[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:5: error: line buffer 't' of n elements is written at 't[i]' (elements 0 to n), which dpgen finds is not always within the buffer [dpgen-buffer]
  for (int i = 0; i < n; ++i)
    out[i] = t[i];
}

DPGEN_KERNEL void pairs(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[400];
  for (int i = 0; i < n; ++i) {
    t[2 * i] = a[i];
    t[2 * i + 1] = a[i] * a[i];
  }
  for (int i = 0; i < 2 * n; ++i)
    out[i] = t[i];
  // CHECK: line_buffers.cpp:[[@LINE-1]]:14: error: line buffer 't' is read at 't[i]', and no earlier loop of the kernel writes it:{{.*}}[dpgen-buffer]
}
