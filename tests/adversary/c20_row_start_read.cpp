// A read that drops the inner counter (`a[j * nx]`, the row's first cell, in
// the loop over i): its adjoint sums over i in each row's cell. With nx = 0
// the loop over i never runs and the kernel reads nothing, but the interior
// cells stored their (empty) sums unconditionally: `a_adj[j * nx] += -0.0`
// outside an empty array. Found with a running index's test (reset_c89).
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void c20_row_start_read(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx,
                                     int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      b[j * nx + i] = a[j * nx + i] * 2.0 + a[j * nx] * a[j * nx + i];
}
