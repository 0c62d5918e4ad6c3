// Loops that step by 2 (issue 20): a red-black Gauss-Seidel half sweep whose
// start alternates with the row (`i = 1 + (j + 1) % 2`) into a separate
// output, a strided loop starting at the outer counter, and a constant
// weight loop `m += 2` that dpgen unrolls (it used to unroll every m, not
// every other one: a wrong adjoint and tangent), and a ring buffer indexed
// by an unrolled counter's parity (b[m % 2]).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void rb_red_sweep(DPGEN_IN const double* u, DPGEN_IN const double* f,
                               DPGEN_OUT double* v, int nx, int ny, double h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1 + (j + 1) % 2; i < nx - 1; i += 2)
      v[j * nx + i] = 0.25 * (u[j * nx + i - 1] + u[j * nx + i + 1] + u[(j - 1) * nx + i] +
                              u[(j + 1) * nx + i] - h2 * f[j * nx + i] * u[j * nx + i]);
}

DPGEN_KERNEL void strided_from_row(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; i += 2)
      out[j * n + i] = a[i] * a[j];
}

DPGEN_KERNEL void even_weights(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double w[6] = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m < 6; m += 2)
      s += w[m] * u[i + m] * u[i + m];
    out[i] = s;
  }
}

// A two-slot ring buffer indexed by the parity of an unrolled counter
// (`b[m % 2]`, `c[m >> 1]`): constants once m is, as C computes them.
DPGEN_KERNEL void ring_parity(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 3; i < n; ++i) {
    double b[2], c[2];
    for (int m = 0; m < 4; ++m) {
      b[m % 2] = a[i - m] * a[i - m];
      c[m >> 1] = a[i - m] + (double)m;
    }
    out[i] = b[0] - 2.0 * b[1] + c[0] * c[1];
  }
}
