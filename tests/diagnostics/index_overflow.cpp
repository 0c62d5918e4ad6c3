// A 3D flat index computed in int: it passes 2^31 on a 1290^3 grid. The
// forward kernel has that limit; the adjoint computes in 64 bits. A warning
// (once per kernel), and the adjoint is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 3
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny, int nz) {
  for (int l = 0; l < nz; ++l)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c = (l * ny + j) * nx + i;
        out[c] = 2.0 * a[c];
        // CHECK: index_overflow.cpp:[[@LINE-1]]:13: warning: index of 'out' is computed in the 32-bit type 'const int' but multiplies 3 sizes and counters ('l * nx * ny + j * nx + i'): past 2^31 elements it overflows in this kernel (the generated adjoint computes it in 64 bits)
        // CHECK-NOT: warning:
      }
}
